// DPV1 alarms through the slave ([IEC 61158-6-3 DPV1 alarms]): sequence mode with 8 alarms like the
// RS4, the alarm written once into a diagnosis, Alarm_Ack via MSAC_C1, no re-send before the ack.
#include "dp/slave/slave_error.h"
#include "tests/dp/slave/slave_harness.h"

namespace rs4sim::dp::testing {
using namespace ::rs4sim::dp::slave;  // the slave under test
namespace {

Config rs4_like() {
  Config c = example_config();
  c.alarm_capacity = 8;
  c.alarm_sequence_numbers = 8;  // [RS4 manual §5.3]: Seq_Nr in specifier bits 5..3 (0..7)
  return c;
}

// Set_Prm with DPV1_Status 80 24 03: diagnostic + update alarms, Alarm_Mode 3 (8 alarms).
const Bytes kAlarmPrm{0x88, 0x0A, 0x01, 0x0B, 0x12, 0x34, 0x00, 0x80, 0x24, 0x03};

AlarmRequest diag_alarm(const Bytes& data) {
  return {1, 0, 1, true, std::span<const std::uint8_t>(data.data(), data.size())};
}

TEST(SlaveAlarms, EightOutstandingInSequenceModeThenWaitForAck) {
  SlaveHarness h(rs4_like());
  h.to_data_exchange(kAlarmPrm);
  ASSERT_TRUE(h.slave.alarms().is_open());
  EXPECT_EQ(h.slave.alarms().limit(), 8U);
  const Bytes data{0x84, 0x24, 0x18, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00};  // [RS4 manual §5.3.2]
                                                                           // shape
  for (int i = 0; i < 9; ++i) ASSERT_FALSE(h.app.control->submit_alarm(diag_alarm(data)));
  for (std::uint8_t seq = 0; seq < 8; ++seq) {
    EXPECT_EQ(h.send(h.dx({0x00}))[6], 0x0A) << "DH announces alarm " << int(seq);
    Bytes expected{0x00,
                   0x0C,
                   0x00,
                   0x02,
                   0x12,
                   0x34,
                   0x0D,  // block length 13 incl. header ([RS4 manual §5.3.2])
                   0x01,  // diagnostic alarm
                   0x00,  // slot 0
                   static_cast<std::uint8_t>((seq << 3) | 0x04 | 0x01)};  // Seq, Add_Ack, appears
    expected.insert(expected.end(), data.begin(), data.end());
    EXPECT_EQ(h.diag(), expected);
  }
  // The 9th waits: no DH, no alarm in the diagnosis, nothing re-sent.
  EXPECT_EQ(h.send(h.dx({0x00}))[6], 0x08);
  EXPECT_EQ(h.diag().size(), 6U);
  EXPECT_EQ(h.slave.alarms().outstanding(), 8U);
  // Alarm_Ack for Seq 2: 5C slot 0, type 1, specifier 0x15.
  EXPECT_EQ(h.send(h.dp(0x33, {0x5C, 0x00, 0x01, 0x15}, 0x33)), kSc);
  EXPECT_EQ(h.send(h.dp(0x33, {}, 0x33)),
            SlaveHarness::reply(0x08, 0x33, 0x33, {0x5C, 0x00, 0x01, 0x15}));
  ASSERT_EQ(h.app.acks.size(), 1U);
  EXPECT_EQ(h.app.acks[0].seq_nr, 2);
  EXPECT_EQ(h.send(h.dx({0x00}))[6], 0x0A);  // the 9th now goes out, with the freed Seq 2
  EXPECT_EQ(h.diag()[9], (2 << 3) | 0x05);
}

TEST(SlaveAlarms, UnmatchedAckLeavesDataExchange) {
  SlaveHarness h(rs4_like());
  h.to_data_exchange(kAlarmPrm);
  ASSERT_FALSE(h.app.control->submit_alarm(diag_alarm({})));
  h.diag();
  EXPECT_EQ(h.send(h.dp(0x33, {0x5C, 0x00, 0x01, 0x0D}, 0x33)), kSc);  // Seq 1: none
  EXPECT_EQ(h.slave.state(), State::kWaitPrm);
  EXPECT_FALSE(h.slave.alarms().is_open());
  EXPECT_EQ(h.app.control->submit_alarm(diag_alarm({})),
            make_error_code(SlaveError::kAlarmsClosed));
}

TEST(SlaveAlarms, TypeMustBeEnabledAndAlarmsNeedDataExch) {
  SlaveHarness h(rs4_like());
  EXPECT_EQ(h.app.control->submit_alarm(diag_alarm({})),
            make_error_code(SlaveError::kAlarmsClosed));
  h.to_data_exchange(kAlarmPrm);
  const AlarmRequest process{2, 0, 1, false, {}};
  EXPECT_EQ(h.app.control->submit_alarm(process),
            make_error_code(SlaveError::kAlarmTypeNotEnabled));
  // RS4 update alarm [RS4 manual §5.3.1]: 04 06 00 0b00sss100.
  ASSERT_FALSE(h.app.control->submit_alarm({6, 0, 0, true, {}}));
  EXPECT_EQ(h.diag(), (Bytes{0x00, 0x0C, 0x00, 0x02, 0x12, 0x34, 0x04, 0x06, 0x00, 0x04}));
}

TEST(SlaveAlarms, AlarmFollowsTheDeviceBlocks) {
  SlaveHarness h(rs4_like());
  h.to_data_exchange(kAlarmPrm);
  ASSERT_FALSE(
      h.app.control->set_device_diagnosis(Bytes{0x05, 0x81, 0x00, 0x00, 0x00}, false, false));
  h.diag();  // fetch the status PDU
  ASSERT_FALSE(h.app.control->submit_alarm({6, 0, 0, true, {}}));
  EXPECT_EQ(h.diag(), (Bytes{0x00, 0x0C, 0x00, 0x02, 0x12, 0x34, 0x05, 0x81, 0x00, 0x00,
                             0x00,                       // PROFIsafe status PDU
                                                         // ([RS4 manual §6.2, §6.3])
                             0x04, 0x06, 0x00, 0x04}));  // update alarm
}

TEST(SlaveAlarms, ExtraAlarmSap50) {
  Config cfg = rs4_like();
  cfg.extra_alarm_sap = true;
  SlaveHarness h(cfg);
  h.to_data_exchange(kAlarmPrm);
  ASSERT_FALSE(h.app.control->submit_alarm({6, 0, 0, true, {}}));
  h.diag();
  EXPECT_EQ(h.send(h.dp(0x32, {0x5C, 0x00, 0x06, 0x04}, 0x33)), kSc);
  EXPECT_EQ(h.send(h.dp(0x32, {}, 0x33)),
            SlaveHarness::reply(0x08, 0x33, 0x32, {0x5C, 0x00, 0x06, 0x04}));
  EXPECT_EQ(h.app.acks.size(), 1U);
}

TEST(SlaveAlarms, LeavingDataExchClosesAndClearsTheQueue) {
  SlaveHarness h(rs4_like());
  h.to_data_exchange(kAlarmPrm);
  ASSERT_FALSE(h.app.control->submit_alarm(diag_alarm({})));
  ASSERT_FALSE(h.app.control->submit_alarm(diag_alarm({})));
  h.advance(std::chrono::milliseconds(100));  // watchdog
  EXPECT_FALSE(h.slave.alarms().is_open());
  EXPECT_EQ(h.slave.alarms().pending() + h.slave.alarms().outstanding(), 0U);
  EXPECT_EQ(h.diag().size(), 6U);
}

}  // namespace
}  // namespace rs4sim::dp::testing
