// bench_rs4_adapter: one cyclic exchange through the adapter (F-output PDU → FDevice →
// scanner inputs → input byte → FDevice → F-input PDU), one acyclic WRITE+READ of
// PROFI_CMD_GET_VERSION, and the memory of one Adapter incl. its Scanner
// (target ≤ 200 KiB per emulated RS4, reported, not asserted).
#include "profisafe/f_host.h"
#include "rs4/adapter/adapter.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <memory>

namespace {

using namespace rs4sim;
using namespace std::chrono_literals;

struct Running {
  Running() : host(profisafe::FHostConfig{params(), 1, {}}) {
    adapter.power_on(now);
    step(3s);
    dp::pdu::SetPrm prm;
    for (auto b : rs4::adapter::kFBlockHeader) prm.user_data.push_back(b);
    for (auto b : profisafe::encode_f_parameters(params())) prm.user_data.push_back(b);
    (void)adapter.check_parameters(prm, now);
    adapter.on_state_change(dp::slave::State::kWaitCfg, dp::slave::State::kDataExch,
                            dp::slave::TransitionReason::kCfgAccepted, now);
    for (int i = 0; i < 1600; ++i) cycle(20ms);  // past the 30 s boot
  }
  static profisafe::FParameters params() {
    profisafe::FParameters p;
    p.wd_time_ms = 1000;
    return p;
  }
  void step(std::chrono::milliseconds d) {
    now += d;
    adapter.on_time(now);
  }
  void cycle(std::chrono::microseconds d) {
    now += d;
    host.set_output(std::span<const std::uint8_t>(&out, 1));
    const auto req = host.request(now);
    std::array<std::uint8_t, 5> pdu{};
    std::copy(req.begin(), req.end(), pdu.begin());
    adapter.on_outputs(pdu, now);
    std::array<std::uint8_t, 5> in{};
    adapter.read_inputs(in, now);
    host.on_pdu(in, now);
  }
  dp::TimePoint now{};
  rs4::adapter::Adapter adapter;
  profisafe::FHost host;
  std::uint8_t out = 0x01;
};

void BM_CyclicExchange(benchmark::State& state) {
  Running r;
  for (auto _ : state) {
    r.cycle(1ms);  // 1 ms bus cycle: a scan every 40 cycles
    benchmark::DoNotOptimize(r.adapter.input_byte());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_CyclicExchange);

void BM_AcyclicVersion(benchmark::State& state) {
  Running r;
  const std::array<std::uint8_t, 5> cmd{0x00, 0x05, 0xFF, 0xFF, 0x90};
  dp::slave::AcyclicRequest w;
  w.service = dp::slave::AcyclicService::kWrite;
  w.index = 2;
  w.length = 5;
  w.data = cmd;
  dp::slave::AcyclicRequest rd;
  rd.service = dp::slave::AcyclicService::kRead;
  rd.index = 2;
  rd.length = 240;
  for (auto _ : state) {
    benchmark::DoNotOptimize(r.adapter.on_acyclic(w, r.now));
    benchmark::DoNotOptimize(r.adapter.on_acyclic(rd, r.now));
  }
}
BENCHMARK(BM_AcyclicVersion);

void BM_MemoryPerAdapter(benchmark::State& state) {
  for (auto _ : state) {
    auto a = std::make_unique<rs4::adapter::Adapter>();
    a->power_on({});
    a->on_time(dp::TimePoint{} + 31s);
    benchmark::DoNotOptimize(a.get());
  }
  rs4::adapter::Adapter a;
  a.power_on({});
  a.on_time(dp::TimePoint{} + 31s);
  state.counters["sizeof_Adapter_B"] = static_cast<double>(sizeof(rs4::adapter::Adapter));
  state.counters["scanner_heap_B"] = static_cast<double>(a.scanner().heap_bytes());
  state.counters["total_KiB"] =
      static_cast<double>(sizeof(rs4::adapter::Adapter) + a.scanner().heap_bytes()) / 1024.0;
}
BENCHMARK(BM_MemoryPerAdapter)->Iterations(20);

}  // namespace
