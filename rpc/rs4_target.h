#pragma once
// What the RS4 services need from the running process (rs4sim run / demo / a test): the
// devices by station address and the clock. Every call is made on the loop thread
// (through rpc::Executor), so the cores see one thread only.

#include "dp/link/memory_bus.h"
#include "dp/time/clock.h"
#include "rs4/device/rs4_device.h"
#include "rs4sim/v1/rs4.pb.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace rs4sim::rpc {

class EventHub;

class Rs4Target {
 public:
  virtual ~Rs4Target() = default;
  [[nodiscard]] virtual std::vector<std::uint8_t> addresses() const = 0;
  // nullptr for an unknown station.
  virtual rs4::device::Rs4Device* device(std::uint8_t address) = 0;
  [[nodiscard]] virtual dp::TimePoint now() const = 0;
  // True when the run is on the manual clock: time moves only through run_until.
  [[nodiscard]] virtual bool simulated() const = 0;
  // Simulated runs: advances time, checking `done` after every bus event, until it holds
  // or `limit` passed; returns done().
  virtual bool run_until(const std::function<bool()>& done, dp::Duration limit) = 0;
  // The simulated bus for bus faults; nullptr on a real link.
  virtual dp::link::MemoryBus* bus() = 0;
  // Runs `f` on the loop after `delay` (simulated runs: advances time by `delay` first).
  virtual void after(dp::Duration delay, std::function<void()> f) = 0;
  // What the run's devices are: "rs4", or the RS-485 device of a LineDeviceTarget.
  [[nodiscard]] virtual std::string kind() const { return "rs4"; }
  // A station of the run that is not an RS4, as the RS4 calls name it ("a GSD station
  // (rs4sim.v1.GsdStations)"); empty when the run has no other station at `address`.
  [[nodiscard]] virtual std::string other_station(std::uint8_t address) const {
    (void)address;
    return {};
  }
  // The source of Observation.StreamEvents (rpc/event_hub.h); nullptr = no event stream.
  virtual EventHub* events() { return nullptr; }
  // The reed contact of the PC adapter (Device.SetPcAdapter). A process that serves the RS4's
  // RS232 port routes it through the port, which opens and closes with it.
  virtual void set_pc_adapter(rs4::device::Rs4Device& device, bool attached, dp::TimePoint now) {
    attached ? device.adapter().attach_pc_adapter(now) : device.adapter().detach_pc_adapter(now);
  }
  // The station's reply timing on a real-time link into `out`; false = none (no such link).
  virtual bool link_timing(std::uint8_t address, v1::LinkTiming& out) {
    (void)address;
    (void)out;
    return false;
  }
  // The PLC side of the station (the simulated bus's F-host) into `out`; false = none.
  virtual bool plc_view(std::uint8_t address, v1::PlcView& out) {
    (void)address;
    (void)out;
    return false;
  }
  // The PLC's ACK_REI to the station's F-host: empty when given, else why not ("this run has
  // no PLC side", "the F-host is in run, not ack-required").
  virtual std::string ack_rei(std::uint8_t address) {
    (void)address;
    return "this run has no PLC side (no F-host of ours on the link)";
  }

 protected:
  Rs4Target() = default;
  Rs4Target(const Rs4Target&) = default;
  Rs4Target& operator=(const Rs4Target&) = default;
};

}  // namespace rs4sim::rpc
