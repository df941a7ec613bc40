// The whole master side of `rs4sim master --link memory` (issue 24): our class 1 master with one
// PROFIsafe F-host per RS4 (Rs4MasterStation) and N simulated RS4s (Rs4Device) on the in-memory
// bus without a wire model, cycle target 10 ms, every RS4 in data exchange with its F-host in RUN.
// The master side's events are drained after every link call, as MasterService does.
//
// Each iteration runs 100 ms of simulated time (10 cycles, 10·N data exchanges). Counters:
//   sim_s_per_s  simulated seconds per CPU second (the single-threaded run's wall time on an idle
//                core); target for 125 RS4s: ≥ 50.
//   per_exchange CPU time per Data_Exchange (seconds, printed with an SI prefix: "2.1u" = 2.1 µs);
//                target: at 125 RS4s within 2× of the 10-station figure.
#include "dp/link/memory_bus.h"
#include "rs4/device/rs4_device.h"
#include "rs4/device/rs4_master_station.h"

#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

namespace rs4sim::rs4::device {
namespace {

using namespace std::chrono_literals;

constexpr std::uint8_t kMasterAddress = 0;  // the RS4s take 1..N (N ≤ 125)
constexpr dp::Duration kSlice = 100ms;

// The events of each link call are drained right after it, like app/master_service.cpp.
class Draining final : public dp::Station {
 public:
  explicit Draining(Rs4MasterStation& inner) : inner_(inner) {
    inner_.set_wake_handler([this] { wake(); });
  }
  [[nodiscard]] std::uint8_t address() const override { return inner_.address(); }
  void on_telegram(const dp::fdl::Telegram& t, dp::TimePoint now) override {
    inner_.on_telegram(t, now);
    drain();
  }
  void on_time(dp::TimePoint now) override {
    inner_.on_time(now);
    drain();
  }
  [[nodiscard]] std::optional<dp::TimePoint> next_deadline() const override {
    return inner_.next_deadline();
  }
  std::optional<dp::fdl::Telegram> take_transmit() override { return inner_.take_transmit(); }
  void on_malformed_frame(std::error_code why) override { inner_.on_malformed_frame(why); }
  [[nodiscard]] std::size_t events() const { return events_seen_; }

 private:
  void drain() {
    events_.clear();
    inner_.take_events(events_);
    events_seen_ += events_.size();
  }
  Rs4MasterStation& inner_;
  std::vector<Rs4MasterEvent> events_;
  std::size_t events_seen_ = 0;
};

struct MasterSegment {
  dp::ManualClock clock;
  std::unique_ptr<Rs4MasterStation> station;
  std::unique_ptr<Draining> draining;
  std::vector<std::unique_ptr<Rs4Device>> devices;
  std::unique_ptr<dp::link::MemoryBus> bus;

  explicit MasterSegment(std::size_t n) {
    Rs4MasterStationConfig c;
    c.master_address = kMasterAddress;
    c.auto_ack_rei = true;
    for (std::size_t i = 1; i <= n; ++i) {
      Rs4MasterOptions o;
      o.address = static_cast<std::uint8_t>(i);
      c.slaves.push_back(o);
      Rs4DeviceConfig d;
      d.switches = switches_for(o.address);
      d.boot_time = 100ms;
      devices.push_back(std::make_unique<Rs4Device>(d));
    }
    station = std::make_unique<Rs4MasterStation>(c);
    draining = std::make_unique<Draining>(*station);
    bus = std::make_unique<dp::link::MemoryBus>(clock);
    bus->attach(*draining);
    for (auto& d : devices) bus->attach(*d);
    bus->start();
    for (auto& d : devices) d->power_on(clock.now());
  }

  [[nodiscard]] bool all_running() const {
    for (const auto a : station->slave_addresses()) {
      const auto v = station->view(a);
      if (!v || !v->data_exchange() || v->safety != profisafe::FHostState::kRun) return false;
    }
    return true;
  }
  [[nodiscard]] std::uint64_t data_exchanges() const {
    std::uint64_t sum = 0;
    for (const auto a : station->slave_addresses()) {
      sum += station->master().slave_status(a)->counters.data_exchanges;
    }
    return sum;
  }
};

// Out of line so that callgrind can count it alone (--toggle-collect='*one_slice*').
[[gnu::noinline]] void one_slice(MasterSegment& s) { s.bus->run_for(kSlice); }

void BM_MasterWithRs4s(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  MasterSegment s(n);
  s.bus->run_for(5s);  // boot, DP start-up, PROFIsafe start-up
  if (!s.all_running()) {
    state.SkipWithError("not every RS4 in data exchange with PROFIsafe running");
    return;
  }
  const auto exchanges_before = s.data_exchanges();
  std::uint64_t slices = 0;
  for (auto _ : state) {
    one_slice(s);
    ++slices;
  }
  if (!s.all_running()) state.SkipWithError("an RS4 left data exchange during the run");
  const auto exchanges = static_cast<double>(s.data_exchanges() - exchanges_before);
  const double simulated = std::chrono::duration<double>(kSlice).count();
  state.counters["stations"] = static_cast<double>(n);
  state.counters["exchanges_per_slice"] = exchanges / static_cast<double>(slices);
  state.counters["sim_s_per_s"] =
      benchmark::Counter(simulated, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["per_exchange"] =
      benchmark::Counter(exchanges, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_MasterWithRs4s)->Arg(1)->Arg(10)->Arg(50)->Arg(125)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rs4sim::rs4::device
