#pragma once
// The GridScan device tests' rig: the curtain on the shared line rig (stream/testing/
// line_rig.h) at 115200 8N1, where a frame of n bytes is n × 86.8 µs on the wire. Power-up at
// the rig's construction (t0), requests as raw bytes.

#include "gridscan/device.h"
#include "stream/testing/line_rig.h"

#include <gtest/gtest.h>

#include <vector>

namespace rs4sim::gridscan::testing {

using Bytes = std::vector<std::uint8_t>;
using Rig = stream::testing::LineRig<Device>;
using stream::LineFrame;
using namespace std::chrono_literals;

// The wire time of `n` characters at the curtain's 115200 8N1.
inline stream::Duration chars(double n) { return stream::character_time(kLineSettings, n); }

// Power-up and the two power-up messages (A0 at t0, B0 at t0 + 1700 ms), run until the B0
// has arrived (12 characters later) and both forgotten. Returns when the curtain became
// ready: t0 + 1700 ms, the start of the B0; the clock is then 1.04 ms past it.
inline stream::TimePoint boot(Rig& rig) {
  const stream::TimePoint ready = rig.now() + 1700ms;
  rig.run_to(ready + chars(12));
  const auto frames = rig.take();
  EXPECT_EQ(frames.size(), 2U) << "power-up messages";
  return ready;
}

// A valid request for `id` with SeqCnt `seq`.
inline Bytes request(std::uint8_t seq, CommandId id) {
  return encode(Frame{seq, request_id(id), {}});
}

}  // namespace rs4sim::gridscan::testing
