#pragma once
// The two METRON fuzz targets' script: the device on the shared line rig
// (stream/testing/line_rig.h), each frame handed to a check with the time the device gave
// it out (the line's tap, from the line's start), and the script ops both targets share.

#include "metron/device.h"
#include "stream/testing/line_rig.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace rs4sim::metron::fuzzing {

using Rig = stream::testing::LineRig<Device>;
using Check = std::function<void(std::span<const std::uint8_t>, stream::TimePoint)>;

// `check` sees every frame as the device gives it out.
inline stream::FrameTap sent_to(Check check) {
  return [check = std::move(check)](std::span<const std::uint8_t> f, stream::TimePoint now,
                                    stream::FrameDirection d) {
    if (d == stream::FrameDirection::kSent) check(f, now);
  };
}

// Ops 0 (advance `arg` ms) and 1 (`arg` bytes reach the device at once) shared by both
// scripts; false when `op` is another one.
inline bool common_op(Rig& rig, std::uint8_t op, const std::uint8_t*& p, const std::uint8_t* end) {
  const std::uint8_t arg = p < end ? *p++ : 0;
  if (op == 0) {
    rig.run_for(std::chrono::milliseconds(arg));
    (void)rig.take();  // checked as given out
    return true;
  }
  if (op == 1) {
    const std::size_t n = std::min<std::size_t>(arg, static_cast<std::size_t>(end - p));
    rig.send(std::span<const std::uint8_t>(p, n));
    p += n;
    return true;
  }
  --p;  // not ours: the argument byte stays for the caller
  return false;
}

}  // namespace rs4sim::metron::fuzzing
