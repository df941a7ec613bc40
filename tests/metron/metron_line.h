#pragma once
// The METRON tests' rig: the curtain on the shared line rig (stream/testing/line_rig.h),
// 19200 8E1 in slave line mode (a character is 11 bits, 0.573 ms on the wire), and the
// options the tests start from.

#include "metron/device.h"
#include "stream/testing/line_rig.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace rs4sim::metron::testing {

using Bytes = std::vector<std::uint8_t>;
using Rig = stream::testing::LineRig<Device>;
using stream::LineFrame;

inline Options slave_options() { return Options{}; }
inline Options node_options(std::uint8_t node) {
  Options o;
  o.node_enabled = true;
  o.node = node;
  return o;
}

// The line a device with options `o` runs on when the user asks for 9600 baud without
// parity.
inline stream::LineSettings line_asked_for_9600_8n1(Options o) {
  o.baud = 9600;
  o.parity = stream::Parity::kNone;
  return Device(o).line_settings();
}

// The one frame answering `request` within the rig's 100 ms window (a test failure if there
// is not exactly one).
inline Bytes only_reply(Rig& rig, const Bytes& request) {
  const auto s = rig.exchange(request);
  EXPECT_EQ(s.size(), 1U) << "frames answering the request";
  return s.empty() ? Bytes{} : s.front().bytes;
}

}  // namespace rs4sim::metron::testing
