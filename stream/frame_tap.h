#pragma once
// What a runner (dp/link/station_runner.h, stream/byte_runner.h) shows of its traffic: every
// frame (or received chunk) with the runner's `now` and its direction, e.g. to a capture.

#include "stream/clock.h"

#include <cstdint>
#include <functional>
#include <span>

namespace rs4sim::stream {

enum class FrameDirection : std::uint8_t { kReceived, kSent };
using FrameTap =
    std::function<void(std::span<const std::uint8_t> frame, TimePoint now, FrameDirection dir)>;

// The protocol a byte line carries, named in each record of its capture
// (app/runtime/line_capture.h) so that the dissector (tools/wireshark/rs4sim.lua) needs no
// guessing. The values are the capture format's: never renumber.
enum class LineProtocol : std::uint8_t {
  kRaw = 0,        // bytes without a dissector (the echo device)
  kGridScan = 1,   // CEDES frames [GridScan manual §9.2]
  kMetron = 2,     // METRON slave-mode messages and reports [METRON manual]
  kModbusRtu = 3,  // Modbus RTU ADUs (the Polaris) [Modbus over Serial Line V1.02 §2.5.1]
  kRs4Rs232 = 4,   // the RS4's RS232 interface [RS4 manual §5.2.3]
};

}  // namespace rs4sim::stream
