// Class 1 master cost per Data_Exchange ([IEC 61158-6-3 class 1 master cycle]): one iteration = the
// master decides and builds the next request (on_time + take_transmit) and handles the
// slave's DL reply (on_telegram), with N slaves in data exchange, back-to-back cycles.
// The *Wire variant adds the FDL codec work a link does: encode the request to bytes and
// decode the reply frame from bytes.

#include "dp/fdl/decoder.h"
#include "dp/fdl/telegram.h"
#include "dp/master/master.h"

#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace {

using namespace rs4sim::dp;
using namespace rs4sim::dp::master;

constexpr std::size_t kIo = 8;  // bytes of inputs and outputs per slave

SlaveEntry bench_slave(std::uint8_t address) {
  SlaveEntry s;
  s.address = address;
  s.prm.station_status.lock_req = true;
  s.prm.ident_number = 0x1234;
  s.cfg = {0x37};  // 8 bytes in + 8 bytes out (general identifier, [IEC 61158-6-3 Chk_Cfg/Get_Cfg])
  s.input_length = kIo;
  s.output_length = kIo;
  return s;
}

// Replies as a slave that accepts its parameterisation ([IEC 61158-6-3 DP-V0 services] answers per
// DSAP).
std::optional<fdl::Telegram> answer(const fdl::Telegram& req, std::array<bool, 128>& prm) {
  using S = fdl::ResponseStatus;
  const auto ok = [&](S s, std::optional<std::uint8_t> d, std::optional<std::uint8_t> ss,
                      std::span<const std::uint8_t> du) {
    return fdl::make_data_telegram(req.sa, req.da, fdl::FrameControl::response(s), d, ss, du);
  };
  if (req.fc.function() == fdl::RequestFunction::kFdlStatus) return ok(S::kOk, {}, {}, {});
  if (!req.dsap) {
    std::array<std::uint8_t, kIo> in{};
    in.fill(req.da);
    return ok(S::kDataLow, {}, {}, in);
  }
  if (*req.dsap == 60) {
    const bool ready = prm[req.da];
    const std::uint8_t du[] = {static_cast<std::uint8_t>(ready ? 0x00 : 0x02),
                               static_cast<std::uint8_t>(ready ? 0x0C : 0x05),
                               0x00,
                               static_cast<std::uint8_t>(ready ? req.sa : 0xFF),
                               0x12,
                               0x34};
    return ok(S::kDataLow, req.ssap, req.dsap, du);
  }
  if (*req.dsap == 61) prm[req.da] = true;
  return fdl::make_short_ack();
}

struct Bench {
  TimePoint now{std::chrono::hours(1)};
  Master master;
  std::array<bool, 128> prm{};
  std::vector<MasterEvent> events;

  explicit Bench(int slaves) : master(config(slaves)) {
    const auto want = static_cast<std::uint32_t>(slaves);
    for (int i = 0; i < 100'000; ++i) {
      exchange_scripted();
      master.take_events(events);
      bool done = false;
      for (const auto& e : events) {
        if (const auto* c = std::get_if<CycleCompleted>(&e))
          done = c->slaves_in_data_exchange == want;
      }
      events.clear();
      if (done) return;
    }
    throw std::runtime_error("slaves did not reach data exchange");
  }

  static MasterConfig config(int slaves) {
    MasterConfig m;
    m.address = 0;
    m.claim_token = false;
    m.cycle_target = Duration::zero();
    for (int a = 1; a <= slaves; ++a) m.slaves.push_back(bench_slave(static_cast<std::uint8_t>(a)));
    return m;
  }

  std::optional<fdl::Telegram> request() {
    if (auto d = master.next_deadline(); d && *d > now) now = *d;
    master.on_time(now);
    return master.take_transmit();
  }

  // Slave `a`'s DL reply to the master's data exchange request (SRD high, FCV and FCB set).
  std::optional<fdl::Telegram> data_exchange_reply(std::uint8_t a) {
    fdl::Telegram req;
    req.da = a;
    req.sa = 0;
    req.fc = fdl::FrameControl::request(fdl::RequestFunction::kSrdHigh, true, true);
    return answer(req, prm);
  }

  void exchange_scripted() {
    if (auto t = request()) {
      if (auto r = answer(*t, prm)) master.on_telegram(*r, now);
    }
  }
};

void BM_MasterDataExchange(benchmark::State& state) {
  Bench b(static_cast<int>(state.range(0)));
  // Pre-built DL replies per slave: the loop measures the master only.
  std::array<std::optional<fdl::Telegram>, 128> replies;
  for (std::uint8_t a = 1; a <= state.range(0); ++a) {
    replies[a] = b.data_exchange_reply(a);
  }
  for (auto _ : state) {
    auto t = b.request();
    b.master.on_telegram(*replies[t->da], b.now);
    b.master.take_events(b.events);
    b.events.clear();
    benchmark::DoNotOptimize(t);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["cycles"] = static_cast<double>(b.master.counters().cycles);
}
BENCHMARK(BM_MasterDataExchange)->Arg(1)->Arg(32)->Arg(125);

void BM_MasterDataExchangeWire(benchmark::State& state) {
  Bench b(static_cast<int>(state.range(0)));
  std::array<std::vector<std::uint8_t>, 128> replies;
  for (std::uint8_t a = 1; a <= state.range(0); ++a) {
    fdl::encode(*b.data_exchange_reply(a), replies[a]);
  }
  std::vector<std::uint8_t> wire;
  wire.reserve(fdl::kMaxTelegramSize);
  fdl::Telegram reply;
  for (auto _ : state) {
    auto t = b.request();
    wire.clear();
    fdl::encode(*t, wire);
    (void)fdl::decode_frame(replies[t->da], reply);
    b.master.on_telegram(reply, b.now);
    b.master.take_events(b.events);
    b.events.clear();
    benchmark::DoNotOptimize(wire.data());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_MasterDataExchangeWire)->Arg(1)->Arg(125);

}  // namespace
