// The scene as element numbers, the form every device's scene takes: the mask the state
// bytes are built from, worked out by hand, and the refusals that change nothing.
#include "gridscan/scene.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <system_error>
#include <vector>

namespace rs4sim::gridscan {
namespace {

using Numbers = std::vector<std::uint16_t>;

TEST(GridScanScene, ElementNumbersBecomeTheObjectMask) {
  Scene s;
  const Numbers in{22, 1, 60};  // any order
  ASSERT_FALSE(s.set_interrupted(in, 60));
  // element e is bit e-1: 1 → bit 0, 22 → bit 21 (0x20'0000), 60 → bit 59
  EXPECT_EQ(s.blocked, 0x0800'0000'0020'0001ULL);
  EXPECT_EQ(s.interrupted(), (Numbers{1, 22, 60}));
  // the others become free
  ASSERT_FALSE(s.set_interrupted(Numbers{3}, 60));
  EXPECT_EQ(s.blocked, 0x4ULL);
  ASSERT_FALSE(s.set_interrupted(Numbers{}, 60));
  EXPECT_EQ(s.blocked, 0U);
  EXPECT_TRUE(s.interrupted().empty());
}

TEST(GridScanScene, AnElementOutsideTheCurtainChangesNothing) {
  Scene s;
  ASSERT_FALSE(s.set_interrupted(Numbers{5}, 24));
  for (const Numbers& bad : {Numbers{25}, Numbers{0}, Numbers{1, 2, 25}}) {
    EXPECT_EQ(s.set_interrupted(bad, 24), SceneError::kNoSuchElement);
    EXPECT_EQ(s.blocked, 0x10U) << "element 5 still, and only it";
  }
  // 64 elements is the mask's width: element 64 is bit 63, 65 does not exist.
  ASSERT_FALSE(s.set_interrupted(Numbers{64}, 64));
  EXPECT_EQ(s.blocked, 0x8000'0000'0000'0000ULL);
  EXPECT_TRUE(s.set_interrupted(Numbers{65}, 100));
}

TEST(GridScanScene, ElementsOfAMaskStopAtTheCount) {
  EXPECT_EQ(elements_of(0b1011, 3), (Numbers{1, 2}));
  EXPECT_EQ(elements_of(~0ULL, 2), (Numbers{1, 2}));
  EXPECT_TRUE(elements_of(0, 60).empty());
}

}  // namespace
}  // namespace rs4sim::gridscan
