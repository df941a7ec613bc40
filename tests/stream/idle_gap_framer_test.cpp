#include "stream/idle_gap_framer.h"

#include <gtest/gtest.h>

#include <array>

using namespace rs4sim::stream;
using namespace std::chrono_literals;

namespace {
const TimePoint t0{1h};
const std::array<std::uint8_t, 3> kA{0x01, 0x03, 0x00};
const std::array<std::uint8_t, 2> kB{0xC4, 0x0B};
}  // namespace

TEST(IdleGapFramer, ChunksCloserThanTheGapAreOneFrame) {
  IdleGapFramer f(2ms, 256);
  f.feed(kA, t0);
  f.feed(kB, t0 + 1999us);
  EXPECT_EQ(f.deadline(), t0 + 1999us + 2ms);
  EXPECT_FALSE(f.poll(t0 + 3ms));  // still within the gap after the last chunk
  auto frame = f.poll(t0 + 1999us + 2ms);
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->bytes, (std::vector<std::uint8_t>{0x01, 0x03, 0x00, 0xC4, 0x0B}));
  EXPECT_EQ(frame->first_byte, t0);
  EXPECT_FALSE(f.deadline());
  EXPECT_EQ(f.stats().frames, 1U);
}

TEST(IdleGapFramer, AGapOfExactlyTheIdleTimeSplitsFrames) {
  IdleGapFramer f(2ms, 256);
  f.feed(kA, t0);
  f.feed(kB, t0 + 2ms);  // the line was idle for the whole gap: a new frame
  auto first = f.poll(t0 + 2ms);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->bytes.size(), 3U);
  EXPECT_FALSE(f.poll(t0 + 3ms));
  auto second = f.poll(t0 + 4ms);
  ASSERT_TRUE(second);
  EXPECT_EQ(second->bytes.size(), 2U);
}

TEST(IdleGapFramer, OversizedFrameKeepsTheFirstBytesAndIsFlagged) {
  IdleGapFramer f(1ms, 4);
  f.feed(kA, t0);
  f.feed(kB, t0);
  auto frame = f.poll(t0 + 1ms);
  ASSERT_TRUE(frame);
  EXPECT_TRUE(frame->oversized);
  EXPECT_EQ(frame->bytes, (std::vector<std::uint8_t>{0x01, 0x03, 0x00, 0xC4}));
  EXPECT_EQ(f.stats().oversized, 1U);
  // the next frame is not disturbed
  f.feed(kB, t0 + 5ms);
  auto next = f.poll(t0 + 6ms);
  ASSERT_TRUE(next);
  EXPECT_FALSE(next->oversized);
  EXPECT_EQ(next->bytes.size(), 2U);
}

TEST(IdleGapFramer, ResetDropsThePendingFrame) {
  IdleGapFramer f(1ms, 16);
  f.feed(kA, t0);
  f.reset();
  EXPECT_FALSE(f.receiving());
  EXPECT_FALSE(f.poll(t0 + 10ms));
}
