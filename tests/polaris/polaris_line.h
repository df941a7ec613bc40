#pragma once
// The Polaris tests' rig: the barrier on the shared line rig (stream/testing/line_rig.h),
// 19200 8N1 unless the options say otherwise (a character is 10 bits, 0.521 ms on the wire).

#include "polaris/device.h"
#include "stream/testing/line_rig.h"

#include <chrono>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace rs4sim::polaris::testing {

using Bytes = std::vector<std::uint8_t>;
using Answers = std::vector<Bytes>;
using Rig = stream::testing::LineRig<Device>;
using stream::LineFrame;

// Sends `request` now and steps until the first frame the device sends has reached the
// controller (the clock stops at its end), at most `limit`; nullopt when none did.
inline std::optional<LineFrame> reply(Rig& rig, const Bytes& request,
                                      stream::Duration limit = std::chrono::milliseconds(50)) {
  rig.send(request);
  return rig.run_until_received(rig.now() + limit);
}

// Sends `request` now (LineRig::exchange) and returns the bytes of each frame that reached
// the controller within the rig's 100 ms window, oldest first. For "no answer" use
// rig.silent(request): it also holds nothing still on the wire at the window's end.
inline Answers answers(Rig& rig, const Bytes& request) {
  Answers out;
  for (LineFrame& f : rig.exchange(request)) out.push_back(std::move(f.bytes));
  return out;
}

// The wire time of `n` characters on the rig's line.
inline stream::Duration chars(Rig& rig, double n) {
  return stream::character_time(rig.device().line_settings(), n);
}

}  // namespace rs4sim::polaris::testing
