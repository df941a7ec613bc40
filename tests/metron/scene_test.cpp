// Scene::set_interrupted / interrupted() and Device::set_interrupted: a beam outside
// 1..beams() refuses the whole change (metron/scene.h).
#include "metron/device.h"
#include "metron/scene.h"

#include <gtest/gtest.h>

#include <vector>

namespace rs4sim::metron {
namespace {

using Beams = std::vector<std::uint16_t>;

TEST(MetronScene, SetInterruptedReplacesTheSet) {
  Scene s(24);
  EXPECT_FALSE(s.set_interrupted(Beams{13, 9, 10}));
  EXPECT_EQ(s.interrupted(), (Beams{9, 10, 13}));  // ascending
  EXPECT_FALSE(s.set_interrupted(Beams{24, 1}));
  EXPECT_EQ(s.interrupted(), (Beams{1, 24}));  // 9, 10, 13 are free again
  EXPECT_FALSE(s.set_interrupted(Beams{}));
  EXPECT_TRUE(s.interrupted().empty());
}

TEST(MetronScene, ABeamOutsideTheCurtainChangesNothing) {
  Scene s(24);
  ASSERT_FALSE(s.set_interrupted(Beams{3, 4}));
  for (const Beams& bad : {Beams{5, 25}, Beams{0}, Beams{65535}}) {
    const auto e = s.set_interrupted(bad);
    EXPECT_EQ(e, SceneError::kNoSuchBeam);
    EXPECT_EQ(e.category().name(), std::string("metron.scene"));
    EXPECT_EQ(s.interrupted(), (Beams{3, 4}));
  }
}

// The initial scene is in the options, as the GridScan's and the Polaris' are.
TEST(MetronScene, TheInitialSceneIsAnOption) {
  Options o;
  o.blocked = {9, 13};
  EXPECT_EQ(o.validate(), "");
  EXPECT_EQ(Device(o).scene().interrupted(), (Beams{9, 13}));
  o.blocked = {0};
  EXPECT_EQ(o.validate(), "blocked beam 0 outside 1..24");
  o.blocked = {25};
  EXPECT_EQ(o.validate(), "blocked beam 25 outside 1..24");
}

TEST(MetronScene, DeviceSetInterruptedReturnsTheScenesError) {
  Device d(Options{});
  EXPECT_EQ(d.set_interrupted(Beams{2, 25}), SceneError::kNoSuchBeam);
  EXPECT_TRUE(d.scene().interrupted().empty());
  EXPECT_FALSE(d.set_interrupted(Beams{2, 24}));
  EXPECT_EQ(d.scene().interrupted(), (Beams{2, 24}));
  EXPECT_FALSE(d.ossd_on());
}

}  // namespace
}  // namespace rs4sim::metron
