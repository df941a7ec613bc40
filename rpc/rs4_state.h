#pragma once
// The observation messages of rs4sim.v1 from an RS4 device (docs/rpc.md).

#include "dp/link/turnaround.h"
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

// "steady-init" from kSteadyInit and the like.
std::string kebab(std::string_view name);
void fill_input_bits(const rs4::adapter::InputBits& bits, v1::InputBits& out);

// The names the API documents: "steady-init", "sync-running", "wait-for-f-parameters" …
const char* led_name(rs4::adapter::LedState s);
const char* proxy_phase_name(rs4::adapter::ProxyPhase p);
std::string fdevice_name(profisafe::FDeviceState s);

}  // namespace rs4sim::rpc
