// Benchmarks of the RS4 device assembly (issue 4): memory per emulated RS4 (target
// ≤ 200 KiB: dp::slave::Slave + Adapter + Scanner, sizeof + heap) and one bus cycle master ↔ RS4
// including the PROFIsafe F-host and F-device. Figures are reported, never asserted.
#include "bench/heap_in_use.h"
#include "rs4/device/rs4_segment.h"

#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

using rs4sim::bench::heap_per_object;

namespace rs4sim::rs4::device {
namespace {

using namespace std::chrono_literals;

// Memory of N emulated RS4 devices, powered and booted (scanning), per device.
void BM_MemoryPerRs4(benchmark::State& state) {
  const dp::TimePoint t{1h};
  const auto scanning = [&](std::size_t i) {
    Rs4DeviceConfig c;
    c.switches = switches_for(static_cast<std::uint8_t>(i % 126));
    auto d = std::make_unique<Rs4Device>(c);
    d->power_on(t);
    d->on_time(t + 31s);  // booted, scanning
    return d;
  };
  const double per_device = heap_per_object(state, scanning);
  state.counters["sizeof_Rs4Device_B"] = static_cast<double>(sizeof(Rs4Device));
  state.counters["heap_per_device_B"] = per_device;  // incl. the unique_ptr's object
  state.counters["total_per_device_KiB"] = per_device / 1024.0;
}
BENCHMARK(BM_MemoryPerRs4)->Arg(1)->Arg(32)->Arg(125)->Unit(benchmark::kMillisecond);

// One 10 ms master cycle with the RS4 in data exchange and the F-host in RUN:
// Data_Exchange request/response over the memory bus (FDL encode/decode both ways),
// FDevice check + wrap, FHost check + new PDU, adapter and scanner (25 scans/s).
void BM_BusCycleWithProfisafe(benchmark::State& state) {
  Rs4SegmentConfig c;
  c.device.boot_time = 100ms;
  c.auto_ack_rei = true;
  Rs4Segment s(c);
  s.power_on();
  if (!s.run_until([&] { return s.in_data_exchange(); }, 5s))
    state.SkipWithError("no data exchange");
  s.run_for(500ms);
  const auto cycles_before = s.master().counters().cycles;
  for (auto _ : state) s.run_for(10ms);
  const auto cycles = s.master().counters().cycles - cycles_before;
  state.counters["master_cycles"] = static_cast<double>(cycles);
  state.counters["fhost_answers"] = static_cast<double>(s.fhost().counters().answers);
  state.SetItemsProcessed(static_cast<std::int64_t>(cycles));
}
BENCHMARK(BM_BusCycleWithProfisafe)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace rs4sim::rs4::device

BENCHMARK_MAIN();
