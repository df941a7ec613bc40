#pragma once
// What a runner (dp/link/station_runner.h, stream/byte_runner.h) shows of its traffic: every
// frame (or received chunk) with the runner's `now` and its direction, e.g. to a capture.

#include "stream/clock.h"
#include "stream/device_description.h"

#include <cstdint>
#include <functional>
#include <span>

namespace rs4sim::stream {

enum class FrameDirection : std::uint8_t { kReceived, kSent };
using FrameTap =
    std::function<void(std::span<const std::uint8_t> frame, TimePoint now, FrameDirection dir)>;

// The protocol a byte line carries, named in each record of its capture
// (app/runtime/line_capture.h): the line's LinkKind, whose values are the capture format's.
using LineProtocol = LinkKind;

}  // namespace rs4sim::stream
