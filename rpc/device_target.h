#pragma once
// Rs4Target for the RS4s on a real-time link (rs4sim run --link pty|serial|udp --grpc; one
// or more, `--address` repeated: each a station of its own on the same line): the wall clock,
// timers on the run's io_context; no simulated time and no simulated bus, so SimTime and the bus
// faults answer FAILED_PRECONDITION. Events: a timer polls the device every kPollPeriod on the loop
// (each RS4 watched); telegrams come through each RS4's own TappedStation (rpc/tapped_station.h).

#include "dp/link/turnaround.h"
#include "rpc/event_hub.h"
#include "rpc/rs4_target.h"

#include <boost/asio/io_context.hpp>
#include <boost/asio/steady_timer.hpp>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rs4sim::rpc {

class DeviceTarget final : public Rs4Target {
 public:
  static constexpr dp::Duration kPollPeriod = std::chrono::milliseconds(5);

  // One RS4 of the run, by its station address.
  struct Station {
    std::uint8_t address;
    rs4::device::Rs4Device* device;
  };

  // Starts the poll timer on `io` (its handler holds the hub, not this target); stop() ends it,
  // and the loop cannot finish before. `stations`: distinct addresses, in the run's order.
  DeviceTarget(std::vector<Station> stations, const dp::Clock& clock, boost::asio::io_context& io);
  [[nodiscard]] std::vector<std::uint8_t> addresses() const override;
  rs4::device::Rs4Device* device(std::uint8_t address) override;
  [[nodiscard]] dp::TimePoint now() const override { return clock_.now(); }
  [[nodiscard]] bool simulated() const override { return false; }
  bool run_until(const std::function<bool()>& done, dp::Duration) override { return done(); }
  void after(dp::Duration delay, std::function<void()> f) override;
  dp::link::MemoryBus* bus() override { return nullptr; }
  EventHub* events() override { return hub_.get(); }
  void stop();
  // With the RS4's RS232 port served: attach/detach go through it (rs4sim run --rs232); the
  // hook gets the RS4 that Device.SetPcAdapter addressed.
  using PcAdapterHook =
      std::function<void(rs4::device::Rs4Device& device, bool attached, dp::TimePoint now)>;
  void route_pc_adapter(PcAdapterHook hook) { pc_adapter_hook_ = std::move(hook); }
  void set_pc_adapter(rs4::device::Rs4Device& device, bool attached, dp::TimePoint now) override {
    if (pc_adapter_hook_) {
      pc_adapter_hook_(device, attached, now);
    } else {
      Rs4Target::set_pc_adapter(device, attached, now);
    }
  }

  // The replies' turnaround of the link's stations (app: the StationRunner's), read on the
  // loop; `slot_time_us` = --tsl.
  using TurnaroundSource = dp::link::TurnaroundSource;
  void set_link_timing(TurnaroundSource source, std::optional<std::int64_t> slot_time_us) {
    turnaround_ = std::move(source);
    slot_time_us_ = slot_time_us;
  }
  bool link_timing(std::uint8_t address, v1::LinkTiming& out) override;
  // The run's stations that are not RS4s (a bus file's), by address: what the RS4 calls say
  // for them (RunTarget::other_station).
  void set_other_stations(std::map<std::uint8_t, std::string> others) {
    others_ = std::move(others);
  }
  [[nodiscard]] std::string other_station(std::uint8_t address) const override {
    const auto it = others_.find(address);
    return it == others_.end() ? std::string() : it->second;
  }
  // The RS4s, then the other stations (generic DP slaves).
  [[nodiscard]] std::vector<RunStation> stations() const override {
    auto out = RunTarget::stations();
    for (const auto& [address, what] : others_) {
      out.push_back({address, stream::DeviceKind::kGeneric});
    }
    return out;
  }

 private:
  std::map<std::uint8_t, std::string> others_;
  TurnaroundSource turnaround_;
  std::optional<std::int64_t> slot_time_us_;
  std::vector<Station> stations_;
  const dp::Clock& clock_;
  boost::asio::io_context& io_;
  std::shared_ptr<EventHub> hub_ = std::make_shared<EventHub>();
  // Weak: the timer lives in its own handler and dies with the loop, which may end before
  // this target (a timer must not outlive its io_context).
  std::weak_ptr<boost::asio::steady_timer> poll_timer_;
  std::shared_ptr<bool> stopped_ = std::make_shared<bool>(false);
  PcAdapterHook pc_adapter_hook_;
};

// The RunTarget of a real-time run without RS4s (rs4sim run --device gridscan|metron|polaris
// --grpc, and a lone GSD station's, kind "gsd"): only the event source, so that
// Observation.StreamEvents carries the device's changes (its watcher, rpc/items_watcher.h) with the
// same timer as DeviceTarget; the Observation RPCs for an RS4 answer FAILED_PRECONDITION naming the
// device's own service.
class LineDeviceTarget final : public RunTarget {
 public:
  // `kind`: kGridScan, kMetron, kPolaris, kGeneric (a GSD station). Starts the poll timer as DeviceTarget
  // does. Real time: run_until() only checks `done`, after() is not offered (nothing of such
  // a run schedules through it: SimTime answers FAILED_PRECONDITION on a real-time clock).
  LineDeviceTarget(stream::DeviceKind kind, std::unique_ptr<Watcher> watcher,
                   const dp::Clock& clock, boost::asio::io_context& io);
  [[nodiscard]] std::vector<std::uint8_t> addresses() const override { return {address_}; }
  [[nodiscard]] dp::TimePoint now() const override { return clock_.now(); }
  [[nodiscard]] bool simulated() const override { return false; }
  bool run_until(const std::function<bool()>& done, dp::Duration) override { return done(); }
  void after(dp::Duration, std::function<void()>) override {}
  dp::link::MemoryBus* bus() override { return nullptr; }
  EventHub* events() override { return hub_.get(); }
  [[nodiscard]] stream::DeviceKind kind() const override { return kind_; }
  void stop();

 private:
  stream::DeviceKind kind_;
  std::uint8_t address_;
  const dp::Clock& clock_;
  std::shared_ptr<EventHub> hub_ = std::make_shared<EventHub>();
  std::weak_ptr<boost::asio::steady_timer> poll_timer_;
  std::shared_ptr<bool> stopped_ = std::make_shared<bool>(false);
};

}  // namespace rs4sim::rpc
