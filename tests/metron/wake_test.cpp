// The wake contract [stream/byte_device.h point 4]: the curtain's setters (beams, input,
// synchronism) move neither its deadline nor its transmit queue, so they need no wake; on a
// stream::MemoryLine that reads the deadline only after its calls and on a wake, the next
// report goes out at its scan cycle with the new scene.
#include "tests/metron/metron_line.h"

#include <gtest/gtest.h>

#include <chrono>

namespace rs4sim::metron::testing {
namespace {

using std::chrono::milliseconds;

TEST(MetronWake, ASceneChangeFromOutsideIsInTheNextReportOnTime) {
  Options o;
  o.line_mode = LineMode::kStandard;
  o.reporting_mode = ReportingMode::kContinuous;
  Rig rig(o);  // the line starts at t0
  const auto t0 = rig.now();
  rig.run_to(t0 + milliseconds(25));
  const auto before = rig.take();
  ASSERT_FALSE(before.empty());
  const std::vector<std::uint16_t> beams{9, 10, 11, 12, 13};
  rig.device().set_interrupted(beams);
  rig.run_to(t0 + milliseconds(35));
  const auto got = rig.take();
  ASSERT_EQ(got.size(), 1U);
  // A report every scan cycle (10 ms) from the start; first, last, count = 9, 13, 5
  // (docs/metron.md "Example bytes").
  EXPECT_EQ((got[0].start - t0) % milliseconds(10), stream::Duration::zero());
  EXPECT_EQ(got[0].bytes, (Bytes{0x02, 0x09, 0x0D, 0x05, 0x03}));
}

}  // namespace
}  // namespace rs4sim::metron::testing
