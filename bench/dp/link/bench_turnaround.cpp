// The turnaround statistics' cost per telegram (dp/link/turnaround.h, docs/serial.md): the
// StationRunner's reply path (decode the request, the station, encode, Transport::send) with a
// null transport, without statistics (the baseline) and with them (one clock read and one
// histogram update per reply), and both interleaved in one run for their ratio.
#include "dp/link/station_runner.h"

#include <benchmark/benchmark.h>

#include <vector>

namespace rs4sim::dp::link {
namespace {

// A slave that answers every request to it with a fixed 8-byte Data_Exchange reply, handed out
// from its own storage (no copy, as the real cores do).
class ReplyStation final : public Station {
 public:
  ReplyStation() {
    const std::vector<std::uint8_t> data(8, 0x5A);
    reply_ =
        fdl::make_data_telegram(2, 5, fdl::FrameControl::response(fdl::ResponseStatus::kDataLow),
                                std::nullopt, std::nullopt, data);
  }
  [[nodiscard]] std::uint8_t address() const override { return 5; }
  void on_telegram(const fdl::Telegram& t, TimePoint) override { pending_ = t.da == 5; }
  void on_time(TimePoint) override {}
  [[nodiscard]] std::optional<TimePoint> next_deadline() const override { return std::nullopt; }
  std::optional<fdl::Telegram> take_transmit() override { return std::nullopt; }
  const fdl::Telegram* next_transmit(fdl::Telegram&) override {
    if (!pending_) return nullptr;
    pending_ = false;
    return &reply_;
  }

 private:
  fdl::Telegram reply_;
  bool pending_ = false;
};

class NullTransport final : public Transport {
 public:
  [[nodiscard]] bool datagram() const override { return false; }
  void start(BytesFn on_bytes, ErrorFn) override { deliver = std::move(on_bytes); }
  void send(std::span<const std::uint8_t> frame) override { bytes += frame.size(); }
  void close() override {}
  BytesFn deliver;
  std::size_t bytes = 0;
};

struct Line {
  explicit Line(bool timed) {
    RunnerOptions o;
    o.turnaround = timed;
    runner.emplace(io, clock, transport, o);
    runner->add(station);
    runner->start();
    const std::vector<std::uint8_t> out(8, 0x11);
    fdl::encode(fdl::make_data_telegram(
                    5, 2, fdl::FrameControl::request(fdl::RequestFunction::kSrdHigh, true, true),
                    std::nullopt, std::nullopt, out),
                request);
  }
  void exchange() { transport.deliver(request); }
  boost::asio::io_context io;
  RealClock clock;
  NullTransport transport;
  ReplyStation station;
  std::optional<StationRunner> runner;
  std::vector<std::uint8_t> request;
};

void BM_ReplyPath(benchmark::State& state) {
  Line line(state.range(0) != 0);
  for (auto _ : state) line.exchange();
  benchmark::DoNotOptimize(line.transport.bytes);
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(state.range(0) != 0 ? "with turnaround statistics" : "baseline: no statistics");
}
BENCHMARK(BM_ReplyPath)->Arg(0)->Arg(1);

// Both paths in the same run, alternating batches, so the machine's load hits both alike:
// `ratio` = time with statistics / time without, `extra_ns` = the difference per telegram.
void BM_TurnaroundCostRatio(benchmark::State& state) {
  Line base(false), timed(true);
  constexpr int kBatch = 2000;
  std::chrono::nanoseconds t_base{}, t_timed{};
  for (auto _ : state) {
    auto t0 = SteadyClock::now();
    for (int i = 0; i < kBatch; ++i) base.exchange();
    auto t1 = SteadyClock::now();
    for (int i = 0; i < kBatch; ++i) timed.exchange();
    auto t2 = SteadyClock::now();
    t_base += t1 - t0;
    t_timed += t2 - t1;
  }
  const double n = static_cast<double>(state.iterations()) * kBatch;
  state.counters["base_ns"] = static_cast<double>(t_base.count()) / n;
  state.counters["timed_ns"] = static_cast<double>(t_timed.count()) / n;
  state.counters["extra_ns"] = static_cast<double>((t_timed - t_base).count()) / n;
  state.counters["ratio"] =
      static_cast<double>(t_timed.count()) / static_cast<double>(t_base.count());
  if (timed.runner->turnaround(5)->count() == 0) state.SkipWithError("no reply was timed");
}
BENCHMARK(BM_TurnaroundCostRatio);

}  // namespace
}  // namespace rs4sim::dp::link
