// Error memory of the adapter ([RS4 manual §5.2.2] tables 5.2-7/5.2-8): ring of 20,
// write index of the newest entry, age flag, counts since power-on.
#include "rs4/adapter/error_memory.h"

#include <gtest/gtest.h>

namespace rs4sim::rs4::adapter {
namespace {

TEST(ErrorMemory, EmptyMemory) {
  ErrorMemory m;
  EXPECT_TRUE(m.empty(Processor::kUc1));
  EXPECT_EQ(m.last_error(), protocol::LastErrorAnswer{});
  EXPECT_EQ(m.ring(Processor::kUc2).write_index, 19);  // first push lands in slot 0
  EXPECT_EQ(m.ring(Processor::kUc2).age_flag, 1);
}

TEST(ErrorMemory, RecordCountsAndAges) {
  ErrorMemory m;
  m.record(Processor::kUc2, 0x2600);
  m.record(Processor::kUc2, 0x2A05);
  m.record(Processor::kUc2, 0x2600);
  EXPECT_EQ(m.ring(Processor::kUc2).write_index, 2);
  EXPECT_EQ(m.ring(Processor::kUc2).entries[0], 0x2600);
  EXPECT_EQ(m.ring(Processor::kUc2).entries[1], 0x2A05);
  EXPECT_EQ(m.ring(Processor::kUc2).age_flag, 0);  // occurred in this cycle
  EXPECT_EQ(m.count(Processor::kUc2, 0x2600), 2);
  EXPECT_EQ(m.count(Processor::kUc1, 0x2600), 0);
  EXPECT_EQ(m.last_error().uc2_error, 0x2600);
  EXPECT_EQ(m.last_error().uc2_count, 2);
  m.end_cycle();  // the cycle with the errors ends: still 0
  EXPECT_EQ(m.ring(Processor::kUc2).age_flag, 0);
  m.end_cycle();  // a cycle without a new error: older → 1
  EXPECT_EQ(m.ring(Processor::kUc2).age_flag, 1);
}

TEST(ErrorMemory, RingWrapsAfter20) {
  ErrorMemory m;
  for (std::uint16_t i = 1; i <= 21; ++i) m.record(Processor::kUc1, i);
  EXPECT_EQ(m.ring(Processor::kUc1).write_index, 0);
  EXPECT_EQ(m.ring(Processor::kUc1).entries[0], 21);  // overwrote the oldest
  EXPECT_EQ(m.ring(Processor::kUc1).entries[1], 2);
  m.clear();
  EXPECT_TRUE(m.empty(Processor::kUc1));
}

TEST(ErrorMemory, CountSaturates) {
  ErrorMemory m;
  for (unsigned i = 0; i < 70000; ++i) m.record(Processor::kUc1, 0x2418);
  EXPECT_EQ(m.count(Processor::kUc1, 0x2418), 0xFFFF);
}

}  // namespace
}  // namespace rs4sim::rs4::adapter
