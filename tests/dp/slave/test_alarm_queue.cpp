// AlarmQueue unit tests ([IEC 61158-6-3 DPV1 alarms]): limits per Alarm_Mode, Seq_Nr
// assignment, type enables, acknowledge matching.
#include "dp/slave/alarm_queue.h"
#include "dp/slave/slave_error.h"

#include <gtest/gtest.h>

namespace rs4sim::dp {
using namespace ::rs4sim::dp::slave;  // the slave under test
namespace {

pdu::Dpv1Status sequence_mode(std::uint8_t alarm_mode) {
  pdu::Dpv1Status d;
  d.dpv1_enable = true;
  d.enable_diagnostic_alarm = true;
  d.enable_update_alarm = true;
  d.alarm_mode = alarm_mode;
  return d;
}

TEST(AlarmQueue, ClosedRefusesAlarms) {
  AlarmQueue q(8, 8, 32);
  EXPECT_EQ(q.submit({1, 0, 1, true, {}}), make_error_code(SlaveError::kAlarmsClosed));
}

TEST(AlarmQueue, InvalidFieldsAreRefusedEvenWhenOpen) {
  AlarmQueue q(8, 8, 32);
  q.open(sequence_mode(3));
  EXPECT_EQ(q.submit({0, 0, 1, false, {}}), make_error_code(SlaveError::kInvalidAlarm));  // type 0
  EXPECT_EQ(q.submit({7, 0, 1, false, {}}),
            make_error_code(SlaveError::kInvalidAlarm));  // reserved 7
  EXPECT_EQ(q.submit({127, 0, 1, false, {}}), make_error_code(SlaveError::kInvalidAlarm));  // 127
  EXPECT_EQ(q.submit({1, 255, 1, false, {}}), make_error_code(SlaveError::kInvalidAlarm));  // slot
  EXPECT_EQ(q.submit({1, 0, 4, false, {}}), make_error_code(SlaveError::kInvalidAlarm));    // spec
  EXPECT_EQ(q.submit({2, 0, 1, false, {}}), make_error_code(SlaveError::kAlarmTypeNotEnabled));
}

TEST(AlarmQueue, SequenceModeEightOutstandingThenWaitsForAck) {
  AlarmQueue q(8, 8, 32);
  q.open(sequence_mode(3));  // Alarm_Mode 3 = 8 outstanding ([IEC 61158-6-3 DPV1_Status])
  EXPECT_EQ(q.limit(), 8U);
  for (int i = 0; i < 10; ++i) ASSERT_FALSE(q.submit({1, 0, 1, true, {}}));
  for (std::uint8_t i = 0; i < 8; ++i) {
    auto a = q.take_next();
    ASSERT_TRUE(a);
    EXPECT_EQ(a->seq_nr, i);
  }
  EXPECT_FALSE(q.take_next());  // 9th waits: not re-sent, not dropped
  EXPECT_EQ(q.pending(), 2U);
  EXPECT_FALSE(q.acknowledge(0, 1, 9));  // no such Seq_Nr
  EXPECT_TRUE(q.acknowledge(0, 1, 3));
  EXPECT_FALSE(q.acknowledge(0, 1, 3));  // already acknowledged
  auto next = q.take_next();
  ASSERT_TRUE(next);
  EXPECT_EQ(next->seq_nr, 3);  // the only free number among 0..7
}

TEST(AlarmQueue, LimitIsTheSmallerOfAlarmModeAndCapacity) {
  AlarmQueue q(8, 32, 32);
  q.open(sequence_mode(7));  // master allows 32
  EXPECT_EQ(q.limit(), 8U);
  q.open(sequence_mode(1));  // master allows 2
  EXPECT_EQ(q.limit(), 2U);
}

TEST(AlarmQueue, TypeModeOnePerTypeOthersOvertake) {
  AlarmQueue q(8, 32, 32);
  q.open(sequence_mode(0));
  ASSERT_FALSE(q.submit({1, 0, 1, false, {}}));
  ASSERT_FALSE(q.submit({1, 0, 2, false, {}}));
  ASSERT_FALSE(q.submit({6, 0, 0, true, {}}));
  auto a = q.take_next();
  ASSERT_TRUE(a);
  EXPECT_EQ(a->type, 1);
  auto b = q.take_next();
  ASSERT_TRUE(b);
  EXPECT_EQ(b->type, 6);  // the second diagnostic alarm must wait for the first's ack
  EXPECT_FALSE(q.take_next());
  EXPECT_TRUE(q.acknowledge(0, 1, a->seq_nr));
  auto c = q.take_next();
  ASSERT_TRUE(c);
  EXPECT_EQ(c->specifier, 2);
}

TEST(AlarmQueue, QueueFullAndCloseClears) {
  AlarmQueue q(8, 8, 2);
  q.open(sequence_mode(3));
  ASSERT_FALSE(q.submit({1, 0, 1, false, {}}));
  ASSERT_FALSE(q.submit({1, 0, 1, false, {}}));
  EXPECT_EQ(q.submit({1, 0, 1, false, {}}), make_error_code(SlaveError::kAlarmQueueFull));
  q.close();
  EXPECT_EQ(q.pending(), 0U);
  EXPECT_FALSE(q.is_open());
}

TEST(AlarmQueue, BlockBytesMatchTheRs4UpdateAlarm) {
  // [RS4 manual §5.3.1] update alarm: 04 06 00 0b00sss100 — seq 5 → specifier 0x2C.
  Alarm a;
  a.type = 6;
  a.slot = 0;
  a.add_ack = true;
  a.seq_nr = 5;
  std::vector<std::uint8_t> out;
  a.append_block(out);
  EXPECT_EQ(out, (std::vector<std::uint8_t>{0x04, 0x06, 0x00, 0x2C}));
}

}  // namespace
}  // namespace rs4sim::dp
