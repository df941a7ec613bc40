#pragma once
// rpc::Rs4Target over a segment app/ builds on the in-memory bus with our master (a GSD
// segment, a bus file's segment): its RS4s, its GSD stations and the stations without an API,
// on the segment's manual clock. Time moves only through run_until/after (SimTime); the bus
// faults act on the segment's bus. Events: every RS4 and GSD station is watched, and a bus
// observer gives the hub their telegrams and polls it after every bus event. The RS4 calls for
// a GSD station or a generic slave answer FAILED_PRECONDITION naming what it is.

#include "app/devices/device_registry.h"
#include "dp/link/memory_bus.h"
#include "dp/time/clock.h"
#include "rpc/event_hub.h"
#include "rpc/rs4_target.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace rs4sim::app {

class MemoryBusTarget final : public rpc::Rs4Target {
 public:
  // `drain` runs after every bus event while SimTime moves the clock (the master's events);
  // the segment owns `clock`, `bus` and the stations and outlives this target. Adds the bus
  // observer (it holds the hub, not this target: the bus may call it after the target).
  MemoryBusTarget(dp::ManualClock& clock, dp::link::MemoryBus& bus, std::function<void()> drain,
                  ServedStations stations);
  [[nodiscard]] std::vector<std::uint8_t> addresses() const override;
  rs4::device::Rs4Device* device(std::uint8_t address) override;
  [[nodiscard]] dp::TimePoint now() const override { return clock_.now(); }
  [[nodiscard]] bool simulated() const override { return true; }
  bool run_until(const std::function<bool()>& done, dp::Duration limit) override;
  void after(dp::Duration delay, std::function<void()> f) override;
  dp::link::MemoryBus* bus() override { return &bus_; }
  rpc::EventHub* events() override { return hub_.get(); }
  // kRs4 with RS4s on the bus; kGeneric for GSD stations alone.
  [[nodiscard]] stream::DeviceKind kind() const override;
  // The RS4s, the GSD stations and the other generic slaves.
  [[nodiscard]] std::vector<rpc::RunStation> stations() const override;
  [[nodiscard]] std::string other_station(std::uint8_t address) const override;

 private:
  dp::ManualClock& clock_;
  dp::link::MemoryBus& bus_;
  std::function<void()> drain_;
  ServedStations stations_;
  std::shared_ptr<rpc::EventHub> hub_ = std::make_shared<rpc::EventHub>();
};

// What the RS4 calls say of a GSD station.
inline constexpr const char* kGsdStationKind = "a GSD station (rs4sim.v1.GsdStations)";

}  // namespace rs4sim::app
