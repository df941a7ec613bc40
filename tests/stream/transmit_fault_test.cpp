#include "stream/transmit_fault.h"

#include <gtest/gtest.h>

using namespace rs4sim::stream;
using namespace std::chrono_literals;

namespace {
const TimePoint t0{1h};
using Bytes = TransmitQueue::Bytes;
}  // namespace

TEST(TransmitQueue, NoFaultFramesLeaveWhenDueInDueOrder) {
  TransmitQueue q;
  const TransmitFault none;
  EXPECT_TRUE(q.schedule({0x02}, t0 + 5ms, none));
  EXPECT_TRUE(q.schedule({0x01}, t0 + 2ms, none));
  EXPECT_TRUE(q.schedule({0x03}, t0 + 5ms, none));  // same time: after the one queued first
  EXPECT_EQ(q.next_due(), t0 + 2ms);
  EXPECT_FALSE(q.pop_due(t0 + 2ms - 1ns));
  EXPECT_EQ(q.pop_due(t0 + 2ms), Bytes{0x01});
  EXPECT_EQ(q.next_due(), t0 + 5ms);
  EXPECT_EQ(q.pop_due(t0 + 9ms), Bytes{0x02});
  EXPECT_EQ(q.pop_due(t0 + 9ms), Bytes{0x03});
  EXPECT_FALSE(q.pop_due(t0 + 9ms));
  EXPECT_FALSE(q.next_due());
  EXPECT_TRUE(q.empty());
}

TEST(TransmitQueue, LateShiftsEachFrameByExactlyTheDelay) {
  TransmitQueue q;
  const TransmitFault late{.late = 50ms};
  EXPECT_TRUE(q.schedule({0xAA}, t0, late));
  EXPECT_EQ(q.next_due(), t0 + 50ms);
  EXPECT_FALSE(q.pop_due(t0 + 50ms - 1ns));  // both sides of the bound
  EXPECT_EQ(q.pop_due(t0 + 50ms), Bytes{0xAA});
  EXPECT_EQ(late.delay(t0), t0 + 50ms);
}

TEST(TransmitQueue, SilentQueuesNothingAndSaysSo) {
  TransmitQueue q;
  EXPECT_FALSE(q.schedule({0x01}, t0, TransmitFault{.silent = true, .late = 5ms}));
  EXPECT_TRUE(q.empty());
  EXPECT_FALSE(q.next_due());
  // clearing the fault: the next frame goes out again
  EXPECT_TRUE(q.schedule({0x02}, t0, TransmitFault{}));
  EXPECT_EQ(q.size(), 1U);
  q.clear();
  EXPECT_TRUE(q.empty());
}
