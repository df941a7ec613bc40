// Watchdog on the manual clock ([IEC 61158-6-3 Set_Prm, watchdog]) and Global_Control
// ([IEC 61158-6-3 Global_Control]).
#include "tests/dp/slave/slave_harness.h"

#include <chrono>

namespace rs4sim::dp::testing {
using namespace ::rs4sim::dp::slave;  // the slave under test
namespace {

using std::chrono::milliseconds;
using std::chrono::nanoseconds;

TEST(SlaveWatchdog, ExpiresAtExactlyFactorTimesBaseNotBefore) {
  SlaveHarness h;
  const TimePoint start = h.clock.now();
  h.to_data_exchange();  // WD_Fact 10·1, base 10 ms → 100 ms
  ASSERT_EQ(h.slave.watchdog_time(), Duration(milliseconds(100)));
  EXPECT_EQ(h.slave.next_deadline(), start + milliseconds(100));
  h.advance(milliseconds(100) - nanoseconds(1));
  EXPECT_EQ(h.slave.state(), State::kDataExch);
  h.advance(nanoseconds(1));
  EXPECT_EQ(h.slave.state(), State::kWaitPrm);
  EXPECT_EQ(h.slave.counters().watchdog_expiries, 1U);
  ASSERT_EQ(h.app.clears.size(), 1U);
  EXPECT_EQ(h.app.clears[0], OutputClear::kLeftDataExchange);
  EXPECT_EQ(h.app.transitions.back().why, TransitionReason::kWatchdog);
  // [IEC 61158-6-3 watchdog]: Station_Not_Ready + Prm_Req; DECISION: the slave forgot its master.
  EXPECT_EQ(h.diag(), (Bytes{0x02, 0x05, 0x00, 0xFF, 0x12, 0x34}));
  EXPECT_EQ(h.send(h.dx({0x01})), (Bytes{0x10, 0x02, 0x05, 0x03, 0x0A, 0x16}));  // RS
  EXPECT_FALSE(h.slave.next_deadline().has_value());
}

TEST(SlaveWatchdog, EveryTelegramFromTheOwnerRetriggersOthersDoNot) {
  SlaveHarness h;
  h.to_data_exchange();
  h.advance(milliseconds(60));
  h.send(h.dx({0x01}));  // retrigger at 60 ms → expires at 160 ms
  h.advance(milliseconds(60));
  h.send(sd2({0x85, 0x83, 0x6D, 0x3C, 0x3E}));  // master 3 reads diag: no retrigger
  h.advance(milliseconds(39));
  EXPECT_EQ(h.slave.state(), State::kDataExch);
  h.advance(milliseconds(1));
  EXPECT_EQ(h.slave.state(), State::kWaitPrm);
}

TEST(SlaveWatchdog, ATelegramArrivingAtTheDeadlineIsTooLate) {
  SlaveHarness h;
  h.to_data_exchange();
  h.clock.advance(milliseconds(100));  // the link has not called on_time() yet
  EXPECT_EQ(h.send(h.dx({0x01})), (Bytes{0x10, 0x02, 0x05, 0x03, 0x0A, 0x16}));
  EXPECT_EQ(h.slave.counters().watchdog_expiries, 1U);
}

TEST(SlaveWatchdog, OneMillisecondBaseAndWaitCfgAndOff) {
  SlaveHarness h;
  // DPV1_Status_1 0x84: DPV1_Enable + WD_Base_1ms; factors 10·3 → 30 ms.
  EXPECT_EQ(h.send(h.dp(0x3D, {0x88, 0x0A, 0x03, 0x0B, 0x12, 0x34, 0x00, 0x84, 0x00, 0x00})), kSc);
  EXPECT_EQ(h.slave.watchdog_time(), Duration(milliseconds(30)));
  h.advance(milliseconds(30));  // also supervised in Wait_Cfg
  EXPECT_EQ(h.slave.state(), State::kWaitPrm);
  // WD_On = 0: no supervision at all.
  EXPECT_EQ(h.send(h.dp(0x3D, {0x80, 0x0A, 0x03, 0x0B, 0x12, 0x34, 0x00, 0x80, 0x00, 0x00})), kSc);
  EXPECT_FALSE(h.slave.next_deadline().has_value());
  EXPECT_EQ(h.diag()[1], 0x04);  // WD_On clear
}

TEST(SlaveWatchdog, ApplicationDeadlineIsFoldedIn) {
  SlaveHarness h;
  h.app.deadline = h.clock.now() + milliseconds(5);
  EXPECT_EQ(h.slave.next_deadline(), h.app.deadline);
  h.advance(milliseconds(4));
  EXPECT_EQ(h.app.time_calls, 0);
  h.advance(milliseconds(1));
  EXPECT_EQ(h.app.time_calls, 1);
}

Bytes gc(std::uint8_t command, std::uint8_t group) {
  return sd2({0xFF, 0x82, 0x46, 0x3A, 0x3E, command, group});  // DA 127, SDN high
}

TEST(SlaveGlobalControl, SyncHoldsOutputsUntilTheNextSync) {
  SlaveHarness h;
  // Station_Status 0xA8: Lock + Sync_Req + WD_On.
  h.to_data_exchange({0xA8, 0x0A, 0x01, 0x0B, 0x12, 0x34, 0x00, 0x80, 0x00, 0x00});
  h.send(h.dx({0x01}));
  EXPECT_TRUE(h.send(gc(0x20, 0x00)).empty());  // Sync
  EXPECT_EQ(h.diag()[1], 0x2C);                 // Sync_Mode + WD_On + bit 2
  h.send(h.dx({0x02}));
  h.send(h.dx({0x03}));
  EXPECT_EQ(h.app.outputs.size(), 1U);  // held
  h.send(gc(0x20, 0x00));
  ASSERT_EQ(h.app.outputs.size(), 2U);
  EXPECT_EQ(h.app.outputs[1], Bytes{0x03});
  h.send(h.dx({0x04}));
  h.send(gc(0x10, 0x00));  // Unsync delivers the held outputs and ends the mode
  ASSERT_EQ(h.app.outputs.size(), 3U);
  EXPECT_EQ(h.app.outputs[2], Bytes{0x04});
  h.send(h.dx({0x05}));
  EXPECT_EQ(h.app.outputs.size(), 4U);
}

TEST(SlaveGlobalControl, FreezeLatchesInputs) {
  SlaveHarness h;
  h.to_data_exchange({0x98, 0x0A, 0x01, 0x0B, 0x12, 0x34, 0x00, 0x80, 0x00, 0x00});  // Freeze_Req
  h.app.inputs = {0x11};
  h.send(gc(0x08, 0x00));  // Freeze
  h.app.inputs = {0x22};
  EXPECT_EQ(h.send(h.dx({0x00}))[7], 0x11);
  EXPECT_EQ(h.diag()[1], 0x1C);  // Freeze_Mode
  h.send(gc(0x04, 0x00));        // Unfreeze
  EXPECT_EQ(h.send(h.dx({0x00}))[7], 0x22);
}

TEST(SlaveGlobalControl, SyncWithoutSyncReqIsNotSupported) {
  SlaveHarness h;
  h.to_data_exchange();
  h.send(gc(0x20, 0x00));
  EXPECT_EQ(h.send(h.dx({0x01}))[6], 0x0A);  // DH: new diagnosis
  EXPECT_EQ(h.diag()[0], 0x10);              // Not_Supported
}

TEST(SlaveGlobalControl, GroupSelectAndOwnerAreChecked) {
  SlaveHarness h;
  h.to_data_exchange({0x88, 0x0A, 0x01, 0x0B, 0x12, 0x34, 0x01, 0x80, 0x00, 0x00});  // group 1
  h.send(gc(0x02, 0x02));  // group 2 only: not for us
  EXPECT_TRUE(h.app.clears.empty());
  h.send(sd2({0xFF, 0x83, 0x46, 0x3A, 0x3E, 0x02, 0x00}));  // master 3: not the owner
  EXPECT_TRUE(h.app.clears.empty());
  h.send(gc(0x02, 0x03));  // groups 1+2
  EXPECT_EQ(h.app.clears.size(), 1U);
}

TEST(SlaveDataExchange, LengthMismatchKeepsOutputsFailSafeEmptyClears) {
  SlaveHarness h;
  h.to_data_exchange({0x88, 0x0A, 0x01, 0x0B, 0x12, 0x34, 0x00, 0xC0, 0x00, 0x00});  // Fail_Safe
  h.send(h.dx({0x01, 0x02}));  // 2 bytes, 1 configured
  EXPECT_TRUE(h.app.outputs.empty());
  EXPECT_EQ(h.slave.counters().output_length_errors, 1U);
  EXPECT_EQ(h.send(h.dx({})).size(), 10U);  // empty DX (SD1 request) still answered
  ASSERT_EQ(h.app.clears.size(), 1U);
  EXPECT_EQ(h.app.clears[0], OutputClear::kFailSafe);
}

}  // namespace
}  // namespace rs4sim::dp::testing

namespace rs4sim::dp::testing {
namespace {

TEST(SlaveGlobalControl, ClearZeroesTheOutputImageSeenByRdOutp) {
  SlaveHarness h;
  h.to_data_exchange();
  h.send(h.dx({0x5A}));
  h.send(sd2({0xFF, 0x82, 0x46, 0x3A, 0x3E, 0x02, 0x00}));
  EXPECT_EQ(h.send(h.dp(0x39, {})), SlaveHarness::reply(0x08, 0x3E, 0x39, {0x00}));
}

TEST(SlaveGlobalControl, SdnToOwnAddressIsNeverAnswered) {
  SlaveHarness h;
  h.to_data_exchange();
  // SDN low (FC 0x44) Global_Control addressed to station 5: executed, silent.
  EXPECT_TRUE(h.send(sd2({0x85, 0x82, 0x44, 0x3A, 0x3E, 0x02, 0x00})).empty());
  EXPECT_EQ(h.app.clears.size(), 1U);
  // SDN Slave_Diag to station 5: silent as well.
  EXPECT_TRUE(h.send(sd2({0x85, 0x82, 0x44, 0x3C, 0x3E})).empty());
}

}  // namespace
}  // namespace rs4sim::dp::testing
