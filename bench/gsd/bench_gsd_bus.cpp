// 125 GSD stations (gsd/station/gsd_station.h) with our master configured from the same GSD on
// the in-memory bus: the time of one poll cycle (the machine's, compared with the wire time of
// the same telegrams at 12 Mbit/s) and the heap share of one station. The GSD is the project's
// compact motor starter test file (2 bytes in and out, DP-V0, 12 Mbit/s supported), so the
// figures compare with bench_dp_link's 125 generic slaves.
#include "app/devices/gsd_segment.h"
#include "bench/heap_in_use.h"

#include <benchmark/benchmark.h>

#include <chrono>

namespace {

using namespace std::chrono_literals;
const std::string kGsd = std::string(RS4SIM_GSD_CORPUS) + "/depart_moteur_fr.gsf";

std::vector<rs4sim::app::GsdStationSpec> specs_of_125() {
  std::vector<rs4sim::app::GsdStationSpec> specs;
  const auto one = rs4sim::app::load_gsd_station(kGsd, {}, 0);
  for (int a = 0; a <= 125; ++a) {
    if (a == 1) continue;  // the master's
    auto s = one;
    s.address = static_cast<std::uint8_t>(a);
    specs.push_back(std::move(s));
  }
  return specs;
}

void BM_GsdBus125_Cycle(benchmark::State& state) {
  rs4sim::app::GsdSegment seg(specs_of_125(), "12M", 1us);
  seg.run_for(2s);
  if (seg.in_data_exchange() != 125) {
    state.SkipWithError("not all 125 GSD stations in data exchange");
    return;
  }
  const auto wire_start = seg.clock().now();
  const auto cycles_start = seg.master().counters().cycles;
  for (auto _ : state) {
    const auto target = seg.master().counters().cycles + 1;
    while (seg.master().counters().cycles < target) seg.run_for(50us);
  }
  const auto cycles = static_cast<double>(seg.master().counters().cycles - cycles_start);
  const auto wire = std::chrono::duration<double>(seg.clock().now() - wire_start).count();
  state.counters["wire_us_per_cycle"] = cycles > 0 ? 1e6 * wire / cycles : 0;
}
BENCHMARK(BM_GsdBus125_Cycle)->Unit(benchmark::kMicrosecond);

void BM_GsdStation_HeapPerStation(benchmark::State& state) {
  const auto spec = rs4sim::app::load_gsd_station(kGsd, {}, 5);
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::size_t before = rs4sim::bench::heap_in_use();
    auto s = std::make_unique<rs4sim::app::GsdStation>(spec);
    bytes = rs4sim::bench::heap_in_use() - before;
    benchmark::DoNotOptimize(s.get());
  }
  // The station and its copy of the spec; the parsed GSD (Device) is shared between stations
  // made from one file.
  state.counters["heap_bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_GsdStation_HeapPerStation);

}  // namespace
