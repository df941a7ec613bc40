// The wake contract [stream/byte_device.h point 4]: the barrier's setters (scene, faults) move
// neither its deadline nor its transmit queue, so they need no wake; on a stream::MemoryLine
// that reads the deadline only after its calls and on a wake, the master's pushes keep their
// times and carry the new scene.
#include "tests/polaris/polaris_line.h"

#include <gtest/gtest.h>

#include <chrono>

namespace rs4sim::polaris {
namespace {

using std::chrono::milliseconds;
using testing::Bytes;

TEST(PolarisWake, ASceneChangeFromOutsideGoesOutWithTheNextPushOnTime) {
  Options o;
  o.beams = 40;
  o.mode = DataMode::kFl4;
  o.role = Role::kMaster;
  o.address = 1;
  o.scan_time = milliseconds(20);
  testing::Rig rig(o);  // the line starts at t0
  const auto t0 = rig.now();
  rig.run_to(t0 + milliseconds(36));  // the push at 20 ms (29 bytes: 15.1 ms on the wire)
  ASSERT_EQ(rig.take().size(), 1U);
  std::vector<std::uint16_t> beams;
  for (std::uint16_t b = 9; b <= 13; ++b) beams.push_back(b);
  for (std::uint16_t b = 25; b <= 34; ++b) beams.push_back(b);
  ASSERT_FALSE(rig.device().set_interrupted(beams, rig.now()));
  Faults late;
  late.transmit.late = milliseconds(3);
  rig.device().set_faults(late);
  rig.run_to(t0 + milliseconds(59));
  const auto got = rig.take();
  ASSERT_EQ(got.size(), 1U);
  EXPECT_EQ(got[0].start, t0 + milliseconds(43));  // the 40 ms push, 3 ms late
  // [Polaris manual §8.2.3] FL4 to slave 1 at register 0: objects 9..13, 25..34.
  EXPECT_EQ(got[0].bytes, (Bytes{0x01, 0x10, 0x00, 0x00, 0x00, 0x0A, 0x14, 0x00, 0x09, 0x00, 0x0D,
                                 0x00, 0x19, 0x00, 0x22, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
                                 0x00, 0x00, 0x00, 0x09, 0x00, 0x22, 0xCA, 0xC3}));
}

}  // namespace
}  // namespace rs4sim::polaris
