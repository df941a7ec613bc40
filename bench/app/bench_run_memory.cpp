// Memory of a simulated run (`rs4sim run --link memory`): the RS4 entry of the device
// registry, built as the run builds it, driven in slices of one simulated second as the run
// drives it, for 1 h and for 24 h of simulated time. Counters: the heap the run added
// (mallinfo2: in use and mmap()ed, MB) and the process's max RSS (MB). Run each length in a
// process of its own, max RSS being the process's peak:
//   bench_run_memory --benchmark_filter=Memory/1/   and   bench_run_memory --benchmark_filter=Memory/24/
// The ctest smoke runs the 1 h one.
#include "app/devices/device_registry.h"

#include <benchmark/benchmark.h>
#include <malloc.h>
#include <sys/resource.h>

#include <chrono>

namespace {

// The heap in use, mmap()ed blocks included (a large vector lives in one).
std::size_t heap_in_use() {
  const auto m = mallinfo2();
  return m.uordblks + m.hblkhd;
}

double max_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // kB on Linux
}

void BM_SimulatedRunMemory(benchmark::State& state) {
  const auto hours = state.range(0);
  for (auto _ : state) {
    rs4sim::app::DeviceOptions options;
    const auto* rs4 = rs4sim::app::find_device("rs4");
    rs4->validate(options);
    const auto heap_before = heap_in_use();
    auto run = rs4->simulate(options);
    for (std::int64_t s = 0; s < hours * 3600; ++s) run->run_for(std::chrono::seconds(1));
    state.counters["heap_MB"] =
        static_cast<double>(heap_in_use() - heap_before) / 1e6;
    state.counters["max_rss_MB"] = max_rss_mb();
    benchmark::DoNotOptimize(run->healthy());
  }
}
BENCHMARK(BM_SimulatedRunMemory)->Arg(1)->Arg(24)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
