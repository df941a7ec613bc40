#pragma once
// The observation messages of rs4sim.v1 from an RS4 device (docs/rpc.md).

#include "dp/link/turnaround.h"
#include "dp/master/slave_handler.h"
#include "profisafe/f_host.h"
#include "rs4/device/rs4_device.h"
#include "rs4sim/v1/rs4.pb.h"

#include <cstdint>
#include <optional>
#include <string>

namespace rs4sim::rpc {

void fill_state(const rs4::device::Rs4Device& device, std::uint8_t address, dp::TimePoint now,
                v1::DeviceState& out);
void fill_contour(const rs4::device::Rs4Device& device, v1::Contour& out);
// A station's reply timing on a real line (dp/link/turnaround.h), `slot_time_us` = --tsl.
void fill_link_timing(const dp::link::TurnaroundStats& stats,
                      std::optional<std::int64_t> slot_time_us, v1::LinkTiming& out);

// The master's counters for a station in ProfiTrace's names (docs/http.md "Station counters").
void fill_dp_counters(const dp::master::PollCounters& c, v1::DpCounters& out);
// The F-host's side of a station into `out` (present, fhost_state, the PLC's input byte and
// its bits, the F-host's error counters); data_exchange and dp are the caller's.
void fill_fhost(const profisafe::FHost& host, std::uint8_t plc_input_byte, v1::PlcView& out);

void fill_input_bits(const rs4::adapter::InputBits& bits, v1::InputBits& out);

}  // namespace rs4sim::rpc
