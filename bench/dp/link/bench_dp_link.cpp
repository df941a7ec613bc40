// bench_dp_link: the in-memory bus against the wire it simulates.
//
// BM_MemoryBusCycle125: one full poll cycle of our master over 125 generic slaves in
// Data_Exch (one Data_Exchange each), processed by the MemoryBus. Reported with the wire
// time the same telegrams would take at 12 Mbit/s
// ([IEC 61158-4-3 UART character, bus parameters, timing] [IEC 61158-2 baud rates]: 11 bit per
// character, TSYN 33 bit before each request, min TSDR 11 bit before each reply) and the ratio wire
// time / simulation time (issue 17's target: ≥ 100). Argument 1: the same with a --capture attached
// (dp/link/capture.h writing every telegram to a pcap file in the temporary directory): the
// cost of capture on a 125-slave cycle. BM_MemoryPerSlave: heap bytes one generic slave costs
// (object + its allocations + its bus port incl. decoder), measured with glibc mallinfo2().
#include "bench/dp/link/bus_of_125.h"
#include "dp/link/capture.h"

#include <benchmark/benchmark.h>

#include <malloc.h>

#include <filesystem>

namespace {

using namespace rs4sim;
using namespace std::chrono_literals;
using bench::bus_of_125;
using bench::one_bus_cycle;

void BM_MemoryBusCycle125(benchmark::State& state) {
  dp::devices::GenericBus b(bus_of_125());
  if (!bench::reach_steady_state(b)) {
    state.SkipWithError("slaves did not reach Data_Exch");
    return;
  }
  const bool captured = state.range(0) != 0;
  const auto file = std::filesystem::temp_directory_path() / "bench_dp_link_capture.pcap";
  dp::link::Capture capture;
  if (captured) {
    if (capture.open(file, dp::link::PcapLinkType::kUser0)) {
      state.SkipWithError("cannot write the capture file");
      return;
    }
    b.bus().add_observer([&capture](const dp::link::BusEvent& e) { capture.on_bus_event(e); });
  }
  std::uint64_t wire_bits = 0, telegrams = 0;
  b.bus().add_observer([&](const dp::link::BusEvent& e) {
    const auto& t = *e.telegram;
    const bool request = t.type == dp::fdl::FrameType::kToken ||
                         (t.type != dp::fdl::FrameType::kShortAck && t.fc.is_request());
    wire_bits += e.wire.size() * 11 + (request ? 33 : 11);
    ++telegrams;
  });
  std::uint64_t cycles = 0;
  for (auto _ : state) {
    one_bus_cycle(b);
    ++cycles;
  }
  const double wire_s_per_cycle =
      static_cast<double>(wire_bits) / 12e6 / static_cast<double>(cycles);
  state.counters["telegrams_per_cycle"] =
      static_cast<double>(telegrams) / static_cast<double>(cycles);
  state.counters["wire_us_per_cycle_12M"] = wire_s_per_cycle * 1e6;
  // Ratio: wire time of a cycle / simulation time of a cycle (s per iteration, inverted rate).
  state.counters["x_faster_than_wire"] =
      benchmark::Counter(wire_s_per_cycle, benchmark::Counter::kIsIterationInvariantRate);
  if (captured) {
    state.counters["captured_records"] = static_cast<double>(capture.records());
    std::error_code ec;
    std::filesystem::remove(file, ec);
  }
}
BENCHMARK(BM_MemoryBusCycle125)->ArgName("capture")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

void BM_MemoryPerSlave(benchmark::State& state) {
  std::size_t per_slave = 0;
  for (auto _ : state) {
    dp::ManualClock clock;
    dp::link::MemoryBus bus(clock);
    std::vector<std::unique_ptr<dp::devices::GenericSlave>> slaves;
    slaves.reserve(125);
    const std::size_t before = mallinfo2().uordblks;  // glibc: bytes in use on the heap
    for (std::uint8_t a = 1; a <= 125; ++a) {
      slaves.push_back(std::make_unique<dp::devices::GenericSlave>(
          dp::devices::GenericSlaveConfig{a, 0x1234, {0x31}, true}));
      bus.attach(*slaves.back());
    }
    per_slave = (mallinfo2().uordblks - before) / 125;
    benchmark::DoNotOptimize(slaves.data());
  }
  state.counters["bytes_per_slave"] = static_cast<double>(per_slave);
  state.counters["sizeof_GenericSlave"] = static_cast<double>(sizeof(dp::devices::GenericSlave));
}
BENCHMARK(BM_MemoryPerSlave)->Unit(benchmark::kMillisecond);

}  // namespace
