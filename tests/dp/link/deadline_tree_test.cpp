// DeadlineTree against the plain definition it replaces: the earliest deadline of all slots,
// ties to the lower slot, none when no slot has one.
#include "dp/link/deadline_tree.h"

#include <gtest/gtest.h>

#include <array>
#include <optional>
#include <random>

namespace rs4sim::dp::link {
namespace {

using Slots = std::array<std::optional<TimePoint>, DeadlineTree::kSlots>;

std::optional<std::pair<TimePoint, std::size_t>> scan(const Slots& s) {
  std::optional<std::pair<TimePoint, std::size_t>> best;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] && (!best || *s[i] < best->first)) best = std::pair{*s[i], i};
  }
  return best;
}

TimePoint at(long ns) { return TimePoint{std::chrono::nanoseconds(ns)}; }

TEST(DeadlineTree, EmptyHasNone) {
  const DeadlineTree t;
  EXPECT_FALSE(t.earliest());
}

TEST(DeadlineTree, TiesGoToTheLowerSlot) {
  DeadlineTree t;
  t.set(9, at(100));
  t.set(3, at(100));
  t.set(70, at(100));
  ASSERT_TRUE(t.earliest());
  EXPECT_EQ(t.earliest()->second, 3U);
}

// The front moving earlier keeps it in front without replaying its path; moving it later
// again must then hand the front to the next earliest (the path it skipped is still right).
TEST(DeadlineTree, FrontMovingEarlierThenLater) {
  DeadlineTree t;
  t.set(0, at(1000));
  t.set(5, at(2000));
  t.set(6, at(1500));
  t.set(0, at(500));  // front, earlier
  EXPECT_EQ(t.earliest(), (std::pair{at(500), std::size_t{0}}));
  t.set(0, at(500));  // front, unchanged
  EXPECT_EQ(t.earliest(), (std::pair{at(500), std::size_t{0}}));
  t.set(0, at(1800));  // front, later: slot 6 takes over
  EXPECT_EQ(t.earliest(), (std::pair{at(1500), std::size_t{6}}));
  t.set(6, std::nullopt);
  EXPECT_EQ(t.earliest(), (std::pair{at(1800), std::size_t{0}}));
}

TEST(DeadlineTree, AMaximalDeadlineIsStillADeadline) {
  DeadlineTree t;
  t.set(4, TimePoint::max());
  EXPECT_EQ(t.earliest(), (std::pair{TimePoint::max(), std::size_t{4}}));
  t.set(2, at(7));
  EXPECT_EQ(t.earliest(), (std::pair{at(7), std::size_t{2}}));
  t.set(2, std::nullopt);
  t.set(4, std::nullopt);
  EXPECT_FALSE(t.earliest());
}

// 200 000 random changes, biased toward what the bus does (the front moving, few distinct
// times so that ties happen), each checked against the scan.
TEST(DeadlineTree, AgreesWithAScanOverRandomChanges) {
  std::mt19937 rng(17);
  DeadlineTree t;
  Slots s{};
  for (int i = 0; i < 200'000; ++i) {
    const auto front = t.earliest();
    std::size_t slot = rng() % DeadlineTree::kSlots;
    if (front && rng() % 2 == 0) slot = front->second;
    std::optional<TimePoint> d;
    switch (rng() % 8) {
      case 0: break;  // cleared
      case 1: d = TimePoint::max(); break;
      default: d = at(static_cast<long>(rng() % 64)); break;
    }
    s[slot] = d;
    t.set(slot, d);
    ASSERT_EQ(t.earliest(), scan(s)) << "change " << i << ", slot " << slot;
  }
}

}  // namespace
}  // namespace rs4sim::dp::link
