// app/demos/narration.h: the progress line and the --realtime pacing of the narrated demos.
#include "app/demos/narration.h"

#include <gtest/gtest.h>

#include <sstream>

namespace rs4sim::app {
namespace {

using namespace std::chrono_literals;

Narration narration(std::ostream& out, dp::ManualClock& clock) {
  return Narration(
      out, clock,
      [&clock](const std::function<bool()>& done, dp::Duration limit) {
        clock.advance(limit);
        return done();
      },
      Narration::Stamp::kSeconds);
}

TEST(NarrationProgress, ALogGetsOnlyTheFinalLine) {
  dp::ManualClock clock;
  std::ostringstream out;
  auto n = narration(out, clock);
  n.progress("upload [##--] 1/2", false);
  EXPECT_EQ(out.str(), "");
  n.progress("upload [####] 2/2", true);
  EXPECT_EQ(out.str(), "[   0.000 s] upload [####] 2/2\n");
}

TEST(NarrationProgress, ATerminalGetsTheLineRedrawnInPlace) {
  dp::ManualClock clock;
  std::ostringstream out;
  auto n = narration(out, clock);
  n.set_live(true);
  n.progress("a", false);
  clock.advance(1500ms);
  n.progress("b", true);
  EXPECT_EQ(out.str(), "\r[   0.000 s] a\r[   1.500 s] b\n");
}

// The pacing waits for the wall clock to catch up with simulated time; it never makes
// simulated time run ahead of the wall clock (a lower bound, not a speed target).
TEST(NarrationRealtime, SimulatedTimeDoesNotOutrunTheWallClock) {
  dp::ManualClock clock;
  int slices = 0;
  const RunUntil run = [&](const std::function<bool()>& done, dp::Duration limit) {
    ++slices;
    clock.advance(limit);
    return done();
  };
  const auto paced = paced_to_wall_clock(run, clock);
  const auto wall0 = std::chrono::steady_clock::now();
  EXPECT_FALSE(paced([] { return false; }, 60ms));
  EXPECT_GE(std::chrono::steady_clock::now() - wall0, 60ms);
  EXPECT_EQ(slices, 6) << "10 ms slices";
  EXPECT_TRUE(paced([] { return true; }, 1s)) << "returns at the first slice where done holds";
}

}  // namespace
}  // namespace rs4sim::app
