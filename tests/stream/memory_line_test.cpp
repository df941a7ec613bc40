// MemoryLine on the manual clock: wire time both ways, deadlines in order, a frame split
// across chunks, a wake from outside, with the echo device (stream/echo_device.h).
#include "stream/memory_line.h"

#include "stream/echo_device.h"

#include <gtest/gtest.h>

namespace rs4sim::stream {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;

// 9600 8N1: 10 bits a character, 1041667 ns (rounded up); the gap 3.5 characters.
constexpr LineSettings k9600{9600, 8, Parity::kNone, 1};

class MemoryLineTest : public ::testing::Test {
 protected:
  ManualClock clock;
  EchoDevice echo{EchoOptions{k9600, 3.5, 2ms, 256}};
  MemoryLine line{clock, echo};
  TimePoint t0 = clock.now();
};

TEST_F(MemoryLineTest, TheEchoArrivesAfterWireTimeGapDelayAndWireTime) {
  line.start();
  const Bytes request = {0x01, 0x03, 0x00, 0x00};  // 4 characters
  line.write(request);
  line.run_for(100ms);
  const auto got = line.take_received();
  ASSERT_EQ(got.size(), 1U);
  EXPECT_EQ(got[0].bytes, request);
  const Duration wire = character_time(k9600, 4);  // 4 × 10 bits at 9600 bit/s
  EXPECT_EQ(wire, 4166667ns);
  // The device had the frame when its last byte arrived (t0 + wire), cut it after 3.5
  // characters of silence, waited its 2 ms delay; the answer took `wire` again.
  const TimePoint cut = t0 + wire + character_time(k9600, 3.5);
  EXPECT_EQ(got[0].start, cut + 2ms);
  EXPECT_EQ(got[0].end, cut + 2ms + wire);
  EXPECT_EQ(clock.now(), t0 + 100ms);
  EXPECT_EQ(line.counters().frames_sent, 1U);
  EXPECT_EQ(line.counters().bytes_received, 4U);
}

TEST_F(MemoryLineTest, NothingArrivesBeforeItsWireTimeHasPassed) {
  line.start();
  line.write(Bytes{0xAA, 0xBB});
  const TimePoint cut = t0 + character_time(k9600, 2) + character_time(k9600, 3.5);
  line.run_until(cut + 2ms + character_time(k9600, 2) - 1ns);
  EXPECT_TRUE(line.take_received().empty());
  EXPECT_EQ(line.next_arrival(), cut + 2ms + character_time(k9600, 2));
  line.run_for(1ns);
  EXPECT_EQ(line.take_received().size(), 1U);
}

TEST_F(MemoryLineTest, AFrameSplitAcrossChunksWithinTheGapIsOneFrame) {
  line.start();
  line.deliver_at(Bytes{0x10, 0x20}, t0 + 1ms);
  line.deliver_at(Bytes{0x30}, t0 + 1ms + character_time(k9600, 3));  // inside 3.5 chars
  line.deliver_at(Bytes{0x40}, t0 + 50ms);                            // a new frame
  line.run_for(100ms);
  const auto got = line.take_received();
  ASSERT_EQ(got.size(), 2U);
  EXPECT_EQ(got[0].bytes, (Bytes{0x10, 0x20, 0x30}));
  EXPECT_EQ(got[1].bytes, Bytes{0x40});
  EXPECT_EQ(echo.framer_stats().frames, 2U);
}

TEST_F(MemoryLineTest, PacedCharactersArriveOneByOneAndStayOneFrame) {
  line.start();
  line.write(Bytes{1, 2, 3, 4, 5}, Pacing::kPerCharacter);
  line.run_for(100ms);
  EXPECT_EQ(line.counters().chunks_received, 5U);
  const auto got = line.take_received();
  ASSERT_EQ(got.size(), 1U);
  EXPECT_EQ(got[0].bytes, (Bytes{1, 2, 3, 4, 5}));
}

TEST_F(MemoryLineTest, BackToBackWritesAndAnswersQueueOnTheLine) {
  line.start();
  // The second write starts when the first has left: no silence between them, one frame
  // (paced per character: whole chunks would arrive one wire time apart).
  line.write(Bytes(10, 0x55), Pacing::kPerCharacter);
  line.write(Bytes(10, 0x66), Pacing::kPerCharacter);
  line.run_for(200ms);
  const auto got = line.take_received();
  ASSERT_EQ(got.size(), 1U);
  EXPECT_EQ(got[0].bytes.size(), 20U);
}

TEST_F(MemoryLineTest, AWakeFromOutsideIsDrainedAtOnceAndArrivesAfterItsWireTime) {
  line.start();
  clock.advance(5ms);
  echo.say(Bytes{0x42});
  EXPECT_EQ(line.counters().frames_sent, 1U);
  std::vector<LineFrame> seen;
  line.set_peer([&](const LineFrame& f) { seen.push_back(f); });
  line.run_for(10ms);
  ASSERT_EQ(seen.size(), 1U);
  EXPECT_EQ(seen[0].start, t0 + 5ms);
  EXPECT_EQ(seen[0].end, t0 + 5ms + character_time(k9600));
  EXPECT_TRUE(line.take_received().empty());
}

TEST_F(MemoryLineTest, TheTapSeesChunksAndFramesWithTheirTimes) {
  std::vector<std::pair<FrameDirection, TimePoint>> tapped;
  line.set_frame_tap([&](std::span<const std::uint8_t>, TimePoint now, FrameDirection d) {
    tapped.emplace_back(d, now);
  });
  line.start();
  line.write(Bytes{0x01});
  line.run_for(50ms);
  ASSERT_EQ(tapped.size(), 2U);
  EXPECT_EQ(tapped[0].first, FrameDirection::kReceived);
  EXPECT_EQ(tapped[0].second, t0 + character_time(k9600));
  EXPECT_EQ(tapped[1].first, FrameDirection::kSent);
}

}  // namespace
}  // namespace rs4sim::stream
