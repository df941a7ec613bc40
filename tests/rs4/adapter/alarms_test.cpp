// Alarms of the adapter ([RS4 manual §5.3]): update alarm, diagnosis
// alarm coming once per error, going after ≥500 ms, re-reported after reconnection.
#include "adapter_rig.h"

namespace rs4sim::rs4::adapter::testing {
namespace {

struct Alarms : ::testing::Test {
  Rig rig;
  void SetUp() override {
    rig.start();
    rig.run(40ms);
  }
};

TEST_F(Alarms, UpdateAlarmOnFirstClass2Write) {
  // COM_CMD_ALIVE (14, option 1): answered in any RS4 state, so no error alarm joins in (a
  // 0x24 before the RS4 scans would be answered with a 0x53 and its diagnosis alarm).
  rig.write(Rig::block({0x14, 0x01}), 2, dp::slave::AcyclicChannel::kC2, /*first=*/true);
  ASSERT_EQ(rig.control.alarms.size(), 1u);
  const auto& a = rig.control.alarms[0];
  EXPECT_EQ(a.type, 6);  // update alarm: 04 06 00 spec
  EXPECT_EQ(a.slot, 0);
  EXPECT_EQ(a.specifier, 0);
  EXPECT_TRUE(a.add_ack);  // specifier bit 2
  EXPECT_TRUE(a.user_data.empty());
  rig.write(Rig::block({0x14, 0x01}), 2, dp::slave::AcyclicChannel::kC2, false);
  EXPECT_EQ(rig.control.alarms.size(), 1u);
}

TEST_F(Alarms, ComingOncePerErrorThenGoingAfter500ms) {
  rig.out_byte = 0x00;  // 0x2600
  rig.run(100ms);
  ASSERT_EQ(rig.alarms_of(1, 1), 1u);
  EXPECT_EQ(rig.control.alarms[0].user_data, (Bytes{
                                                 0x84,        // error from slave
                                                 0x26, 0x00,  // μC2 error
                                                 0x00, 0x01,  // μC2 count
                                                 0x26, 0x00,  // μC1 error
                                                 0x00, 0x01,  // μC1 count
                                             }));
  EXPECT_TRUE(rig.control.alarms[0].add_ack);
  rig.run(1s);  // the error persists: no second coming, no going
  EXPECT_EQ(rig.alarms_of(1, 1), 1u);
  EXPECT_EQ(rig.alarms_of(1, 2), 0u);
  rig.out_byte = 0x01;
  rig.run(400ms);
  EXPECT_EQ(rig.alarms_of(1, 2), 0u);  // < 500 ms without error
  rig.run(200ms);
  EXPECT_EQ(rig.alarms_of(1, 2), 1u);  // going
}

TEST_F(Alarms, EachNewErrorIsANewComingAlarm) {
  rig.write({0x00, 0x05, 0x00, 0x01, 0x90});  // 0x2A0B
  rig.out_byte = 0x00;                        // 0x2600
  rig.run(40ms);
  EXPECT_EQ(rig.alarms_of(1, 1), 2u);
  EXPECT_EQ(rig.control.alarms[1].user_data[1], 0x26);
}

TEST_F(Alarms, PersistingRs4ErrorIsReportedAgainAfterReconnection) {
  ASSERT_TRUE(rig.adapter.scanner().inject_fault(scanner::Fault::kMotorSpeed, rig.now));
  rig.run(100ms);
  ASSERT_EQ(rig.alarms_of(1, 1), 1u);
  EXPECT_EQ(rig.control.alarms[0].user_data, (Bytes{
                                                 0x84,
                                                 0x02,
                                                 0x01,  // μC2 field: the RS4's error 0x0201
                                                 0x00,
                                                 0x01,  // count 1
                                                 0x00,
                                                 0x00,  // μC1: none
                                                 0x00,
                                                 0x00,
                                             }));
  rig.adapter.on_state_change(dp::slave::State::kDataExch, dp::slave::State::kWaitPrm,
                              dp::slave::TransitionReason::kWatchdog, rig.now);
  rig.advance(100ms);
  rig.adapter.on_state_change(dp::slave::State::kWaitCfg, dp::slave::State::kDataExch,
                              dp::slave::TransitionReason::kCfgAccepted, rig.now);
  EXPECT_EQ(rig.alarms_of(1, 1), 2u);
}

TEST_F(Alarms, NoAlarmWhileNotConnected) {
  rig.adapter.on_state_change(dp::slave::State::kDataExch, dp::slave::State::kWaitPrm,
                              dp::slave::TransitionReason::kWatchdog, rig.now);
  rig.write({0x00, 0x05, 0x00, 0x01, 0x90}, 2, dp::slave::AcyclicChannel::kC2);
  EXPECT_TRUE(rig.control.alarms.empty());
  EXPECT_EQ(rig.adapter.error_memory().last_error().uc2_error, 0x2A0B);
}

}  // namespace
}  // namespace rs4sim::rs4::adapter::testing
