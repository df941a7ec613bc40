// Benchmarks of the scanner model (targets in docs/rs4-scanner.md, reported, not asserted):
// contour generation + field evaluation ≥ 20 000 scans/s per core with a typical scene;
// a whole emulated RS4 ≤ 200 KiB (sizeof + heap, reported as counters).
#include "rs4/scanner/parameter_codec.h"
#include "rs4/scanner/scanner.h"

#include <benchmark/benchmark.h>

#include <atomic>
#include <cstdlib>
#include <new>

// Live heap bytes of this process: every allocation carries its size in a header.
namespace {
std::atomic<std::size_t> g_live_heap{0};
constexpr std::size_t kHeader = alignof(std::max_align_t);
}  // namespace

void* operator new(std::size_t n) {
  auto* p = static_cast<unsigned char*>(std::malloc(n + kHeader));
  if (p == nullptr) throw std::bad_alloc();
  *reinterpret_cast<std::size_t*>(p) = n;
  g_live_heap += n;
  return p + kHeader;
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"  // malloc'd in operator new above
#endif
void operator delete(void* p) noexcept {
  if (p == nullptr) return;
  auto* base = static_cast<unsigned char*>(p) - kHeader;
  g_live_heap -= *reinterpret_cast<std::size_t*>(base);
  std::free(base);
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
void operator delete(void* p, std::size_t) noexcept { operator delete(p); }

namespace {

using namespace rs4sim::rs4::scanner;
using std::chrono::milliseconds;

// A typical scene: the walls of a 8 m × 5 m room, a pillar, two legs, a conveyor edge.
void typical_scene(Scene& s) {
  (void)s.add(Polygon{{{-4000, -500}, {4000, -500}, {4000, 4500}, {-4000, 4500}}});
  (void)s.add(Circle{{1500, 2500}, 200});
  (void)s.add(Circle{{-300, 900}, 60});
  (void)s.add(Circle{{-100, 900}, 60});
  (void)s.add(Wall{{-3500, 3000}, {-1500, 3200}});
}

// Iterations as scans per second.
void count_scans(benchmark::State& state) {
  state.counters["scans/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// A scanner in the typical scene, powered on at `now` and booted (30 s); `now` follows.
struct BootedScanner {
  Scanner s;
  TimePoint now{std::chrono::hours(1)};
  BootedScanner() {
    typical_scene(s.edit_scene(now));
    s.power_on(now);
    now += std::chrono::seconds(30);
    s.advance(now);
  }
};

void BM_RenderAndEvaluate(benchmark::State& state) {
  Scene scene;
  typical_scene(scene);
  const ParameterSet params = factory_default();
  Contour contour{};
  for (auto _ : state) {
    scene.render(contour);
    FieldFlags f = evaluate(contour, params.pairs[0]);
    benchmark::DoNotOptimize(f);
  }
  count_scans(state);
}
BENCHMARK(BM_RenderAndEvaluate);

// One full scan of the Scanner per iteration with a moving obstacle (re-render every scan).
void BM_ScannerScanMovingObstacle(benchmark::State& state) {
  BootedScanner b;
  const auto walker = b.s.edit_scene(b.now).add(Circle{{2000, 3000}, 150});
  double dx = 5;
  for (auto _ : state) {
    (void)b.s.edit_scene(b.now).move(walker.value(), dx, 0);
    dx = -dx;
    b.now += milliseconds(40);
    b.s.advance(b.now);
    benchmark::DoNotOptimize(b.s.ossd());
  }
  count_scans(state);
}
BENCHMARK(BM_ScannerScanMovingObstacle);

// Unchanged scene: steady scans cost only the counter update.
void BM_ScannerSteadyScan(benchmark::State& state) {
  BootedScanner b;
  for (auto _ : state) {
    b.now += milliseconds(40);
    b.s.advance(b.now);
    benchmark::DoNotOptimize(b.s.status());
  }
}
BENCHMARK(BM_ScannerSteadyScan);

// Memory of one emulated scanner: sizeof + the heap it holds with the typical scene.
void BM_ScannerMemory(benchmark::State& state) {
  std::size_t heap = 0;
  std::size_t reported = 0;
  for (auto _ : state) {
    const std::size_t before = g_live_heap.load();
    auto* s = new Scanner();
    TimePoint now{std::chrono::hours(1)};
    typical_scene(s->edit_scene(now));
    s->power_on(now);
    s->advance(now + std::chrono::seconds(31));
    heap = g_live_heap.load() - before - sizeof(Scanner);
    reported = s->heap_bytes();
    benchmark::DoNotOptimize(s);
    delete s;
  }
  state.counters["sizeof_bytes"] = static_cast<double>(sizeof(Scanner));
  state.counters["heap_bytes"] = static_cast<double>(heap);
  state.counters["heap_bytes_reported"] = static_cast<double>(reported);
  state.counters["total_KiB"] = static_cast<double>(sizeof(Scanner) + heap) / 1024.0;
}
BENCHMARK(BM_ScannerMemory);

// Iterations as parameter sets (kParameterSetSize bytes each) per second.
void count_sets(benchmark::State& state) {
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(kParameterSetSize));
}

void BM_ParameterSetEncode(benchmark::State& state) {
  const ParameterSet p = factory_default();
  for (auto _ : state) benchmark::DoNotOptimize(encode(p));
  count_sets(state);
}
BENCHMARK(BM_ParameterSetEncode);

void BM_ParameterSetDecodeValidate(benchmark::State& state) {
  const auto bytes = encode(factory_default());
  for (auto _ : state) benchmark::DoNotOptimize(decode_and_validate(bytes));
  count_sets(state);
}
BENCHMARK(BM_ParameterSetDecodeValidate);

void BM_ParameterSetChecksum(benchmark::State& state) {
  const ParameterSet p = factory_default();
  for (auto _ : state) benchmark::DoNotOptimize(checksum(p));
  count_sets(state);
}
BENCHMARK(BM_ParameterSetChecksum);

}  // namespace
