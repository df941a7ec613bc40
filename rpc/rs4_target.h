#pragma once
// What the RS4 services need from the running process (rs4sim run / demo / a test) beyond
// the run itself (run_target.h): the RS4s by station address, their PC adapter, their link
// timing and PLC side. Every call is made on the loop thread (through rpc::Executor), so the
// cores see one thread only.

#include "rpc/run_target.h"
#include "rs4/device/rs4_device.h"
#include "rs4sim/v1/rs4.pb.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace rs4sim::rpc {

class PlcTarget;

class Rs4Target : public RunTarget {
 public:
  // nullptr for an unknown station, or one that is not an RS4.
  virtual rs4::device::Rs4Device* device(std::uint8_t address) = 0;
  [[nodiscard]] stream::DeviceKind kind() const override { return stream::DeviceKind::kRs4; }
  Rs4Target* rs4s() final { return this; }
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
  // The PLC program's outputs and acknowledgement mode (rs4sim.v1.Plc); nullptr: the run
  // has no PLC side of ours.
  virtual PlcTarget* plc() { return nullptr; }
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
