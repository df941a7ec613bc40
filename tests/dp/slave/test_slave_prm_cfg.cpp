// Set_Prm ([IEC 61158-6-3 Set_Prm, DPV1_Status]), Chk_Cfg/Get_Cfg
// ([IEC 61158-6-3 Chk_Cfg/Get_Cfg]), Rd_Inp/Rd_Outp and Set_Slave_Add
// ([IEC 61158-6-3 Set_Slave_Add, Rd_Inp/Rd_Outp]), wrong-state and wrong-master requests
// ([IEC 61158-6-3 slave state machine]).
#include "tests/dp/slave/slave_harness.h"

namespace rs4sim::dp::testing {
using namespace ::rs4sim::dp::slave;  // the slave under test
namespace {

const Bytes kRsTo2{0x10, 0x02, 0x05, 0x03, 0x0A, 0x16};  // SD1 DA 2 SA 5 FC RS

TEST(SlaveSetPrm, IdentMismatchGivesPrmFault) {
  SlaveHarness h;
  const Bytes prm{0x88, 0x0A, 0x01, 0x0B, 0x43, 0x21,  // Ident 0x4321 ≠ 0x1234
                  0x00, 0x80, 0x20, 0x00};
  EXPECT_EQ(h.send(h.dp(0x3D, prm)), kSc);  // SC = received, not accepted
                                            // ([IEC 61158-4-3 short acknowledgement])
  EXPECT_EQ(h.slave.state(), State::kWaitPrm);
  EXPECT_EQ(h.diag(), (Bytes{0x42,  // Prm_Fault + Station_Not_Ready
                             0x05,  // Prm_Req + bit 2
                             0x00, 0xFF, 0x12, 0x34}));
  EXPECT_TRUE(h.app.user_prm.empty());  // the application is not asked
}

TEST(SlaveSetPrm, TooShortAndZeroWatchdogFactorGivePrmFault) {
  SlaveHarness h;
  EXPECT_EQ(h.send(h.dp(0x3D, {0x88, 0x0A, 0x01, 0x0B, 0x12, 0x34})), kSc);  // 6 bytes
  EXPECT_EQ(h.diag()[0], 0x42);
  EXPECT_EQ(h.send(h.dp(0x3D, {0x88, 0x00, 0x01, 0x0B, 0x12, 0x34, 0x00, 0x80, 0x20, 0x00})), kSc);
  EXPECT_EQ(h.diag()[0], 0x42);
  EXPECT_EQ(h.slave.state(), State::kWaitPrm);
}

TEST(SlaveSetPrm, UnsupportedFeaturesGiveNotSupported) {
  Config cfg = example_config();
  cfg.sync_supported = false;
  SlaveHarness h(cfg);
  EXPECT_EQ(h.send(h.dp(0x3D, {0xA8, 0x0A, 0x01, 0x0B, 0x12, 0x34, 0x00, 0x80, 0x20, 0x00})), kSc);
  EXPECT_EQ(h.diag(), (Bytes{0x12,  // Not_Supported + Station_Not_Ready
                             0x05, 0x00, 0xFF, 0x12, 0x34}));
  // DPV1_Status_3 IsoM_Req (bit 4) is not supported either.
  EXPECT_EQ(h.send(h.dp(0x3D, {0x88, 0x0A, 0x01, 0x0B, 0x12, 0x34, 0x00, 0x80, 0x20, 0x10})), kSc);
  EXPECT_EQ(h.diag()[0], 0x12);
  ASSERT_FALSE(h.app.transitions.empty());
  EXPECT_EQ(h.app.transitions.back().why, TransitionReason::kNotSupported);
}

TEST(SlaveSetPrm, UserParametersGoToTheApplicationWhichMayRefuse) {
  SlaveHarness h;
  h.app.prm_verdict = PrmVerdict::kPrmFault;
  const Bytes prm{0x88, 0x0A, 0x01, 0x0B, 0x12, 0x34,
                  0x00, 0x80, 0x20, 0x00, 0xAA, 0xBB};  // User_Prm_Data after the 3 DPV1 bytes
  EXPECT_EQ(h.send(h.dp(0x3D, prm)), kSc);
  ASSERT_EQ(h.app.user_prm.size(), 1U);
  EXPECT_EQ(h.app.user_prm[0], (Bytes{0xAA, 0xBB}));
  EXPECT_EQ(h.diag()[0], 0x42);
  h.app.prm_verdict = PrmVerdict::kAccept;
  EXPECT_EQ(h.send(h.dp(0x3D, prm)), kSc);
  EXPECT_EQ(h.slave.state(), State::kWaitCfg);
  EXPECT_EQ(h.diag(), (Bytes{0x02,  // only Station_Not_Ready: Prm_Fault cleared
                             0x0C,  // WD_On + bit 2, Prm_Req cleared
                             0x00, 0x02, 0x12, 0x34}));
}

TEST(SlaveSetPrm, DpV0SlaveReadsBytes7To9AsUserData) {
  Config cfg = example_config();
  cfg.dpv1 = false;
  SlaveHarness h(cfg);
  EXPECT_EQ(h.send(h.dp(0x3D, SlaveHarness::example_prm())), kSc);
  ASSERT_EQ(h.app.user_prm.size(), 1U);
  EXPECT_EQ(h.app.user_prm[0], (Bytes{0x80, 0x20, 0x00}));
  EXPECT_FALSE(h.slave.dpv1_active());
}

TEST(SlaveSetPrm, NoLockTakesOnlyMinTsdrUnlockReleases) {
  SlaveHarness h;
  h.to_data_exchange();
  EXPECT_EQ(h.slave.min_tsdr(), 11);
  // Station_Status 00: only min TSDR (here 20) is taken over ([IEC 61158-6-3 Set_Prm]).
  EXPECT_EQ(h.send(h.dp(0x3D, {0x00, 0x01, 0x01, 0x14, 0x00, 0x00, 0x00})), kSc);
  EXPECT_EQ(h.slave.min_tsdr(), 20);
  EXPECT_EQ(h.slave.state(), State::kDataExch);
  // Unlock_Req: released, back to Wait_Prm, outputs safe.
  EXPECT_EQ(h.send(h.dp(0x3D, {0x40, 0x01, 0x01, 0x00, 0x12, 0x34, 0x00})), kSc);
  EXPECT_EQ(h.slave.state(), State::kWaitPrm);
  EXPECT_EQ(h.slave.master_address(), 0xFF);
  ASSERT_EQ(h.app.clears.size(), 1U);
  EXPECT_EQ(h.app.clears[0], OutputClear::kLeftDataExchange);
}

TEST(SlaveSetPrm, NewSetPrmInDataExchGoesToWaitCfg) {
  SlaveHarness h;
  h.to_data_exchange();
  EXPECT_EQ(h.send(h.dp(0x3D, SlaveHarness::example_prm())), kSc);
  EXPECT_EQ(h.slave.state(), State::kWaitCfg);
  EXPECT_EQ(h.app.clears.size(), 1U);
}

TEST(SlaveSetPrm, LockedSlaveRefusesSetPrmFromAnotherMaster) {
  SlaveHarness h;
  h.to_data_exchange();
  // Master 3 (SA 0x83): Set_Prm, first frame.
  Bytes body{0x85, 0x83, 0x6D, 0x3D, 0x3E};
  const Bytes prm = SlaveHarness::example_prm();
  body.insert(body.end(), prm.begin(), prm.end());
  EXPECT_EQ(h.send(sd2(body)), (Bytes{0x10, 0x03, 0x05, 0x03, 0x0B, 0x16}));
  EXPECT_EQ(h.slave.state(), State::kDataExch);
  EXPECT_EQ(h.slave.master_address(), 2);
}

TEST(SlaveChkCfg, MismatchGivesCfgFaultAndWaitPrm) {
  SlaveHarness h;
  EXPECT_EQ(h.send(h.dp(0x3D, SlaveHarness::example_prm())), kSc);
  EXPECT_EQ(h.send(h.dp(0x3E, {0x10, 0x21})), kSc);  // 2 bytes out instead of 1
  EXPECT_EQ(h.slave.state(), State::kWaitPrm);
  EXPECT_EQ(h.diag(), (Bytes{0x06,  // Cfg_Fault + Station_Not_Ready
                             0x05, 0x00,
                             0x02,  // Master_Add kept
                             0x12, 0x34}));
}

TEST(SlaveChkCfg, MalformedIdentifiersAreACfgFaultWithoutAskingTheApplication) {
  SlaveHarness h;
  h.app.cfg_verdict = CfgVerdict::kAccept;
  EXPECT_EQ(h.send(h.dp(0x3D, SlaveHarness::example_prm())), kSc);
  EXPECT_EQ(h.send(h.dp(0x3E, {0x40})), kSc);  // special format, input length byte missing
  EXPECT_EQ(h.slave.state(), State::kWaitPrm);
}

TEST(SlaveChkCfg, WrongStateAndWrongMasterAreRs) {
  SlaveHarness h;
  EXPECT_EQ(h.send(h.dp(0x3E, {0x10, 0x20})), kRsTo2);  // Wait_Prm
  EXPECT_EQ(h.send(h.dp(0x3D, SlaveHarness::example_prm())), kSc);
  EXPECT_EQ(h.send(sd2({0x85, 0x83, 0x6D, 0x3E, 0x3E, 0x10, 0x20})),
            (Bytes{0x10, 0x03, 0x05, 0x03, 0x0B, 0x16}));  // master 3 does not own it
  EXPECT_EQ(h.slave.state(), State::kWaitCfg);
}

TEST(SlaveChkCfg, CheckCfgModeIsPassedToTheApplication) {
  SlaveHarness h;
  h.to_data_exchange({0x88, 0x0A, 0x01, 0x0B, 0x12, 0x34, 0x00, 0x80, 0x21, 0x00});
  EXPECT_TRUE(h.app.last_user_check);
}

TEST(SlaveGetCfg, AnsweredInEveryStateWithTheRealConfig) {
  SlaveHarness h;
  EXPECT_EQ(h.send(h.dp(0x3B, {})), SlaveHarness::reply(0x08, 0x3E, 0x3B, {0x10, 0x20}));
}

TEST(SlaveReadIo, RdInpRdOutpOnlyInDataExch) {
  SlaveHarness h;
  EXPECT_EQ(h.send(h.dp(0x38, {})), kRsTo2);
  h.to_data_exchange();
  EXPECT_EQ(h.send(h.dx({0x5A})).size(), 10U);
  EXPECT_EQ(h.send(h.dp(0x38, {})), SlaveHarness::reply(0x08, 0x3E, 0x38, {0x3C}));
  EXPECT_EQ(h.send(h.dp(0x39, {})), SlaveHarness::reply(0x08, 0x3E, 0x39, {0x5A}));
}

TEST(SlaveSap, WrongMasterSapAndUnusedSapsAreRs) {
  SlaveHarness h;
  EXPECT_EQ(h.send(h.dp(0x3C, {}, 0x33)), kRsTo2);  // Slave_Diag from SSAP 51
  EXPECT_EQ(h.send(h.dp(0x35, {0x01})), kRsTo2);    // Ext_User_Prm not activated
  EXPECT_EQ(h.send(h.dp(0x0A, {0x01})), kRsTo2);    // SAP 10
  EXPECT_EQ(h.slave.counters().per_sap[0x3C], 1U);
}

TEST(SlaveSetSlaveAdd, ChangesAddressPersistsAndLocks) {
  SlaveHarness h;
  const Bytes ssa{0x07,        // New_Slave_Add 7
                  0x12, 0x34,  // Ident
                  0x01,        // No_Add_Chg: lock further changes
                  0xEE};       // Rem_Slave_Data
  EXPECT_EQ(h.send(h.dp(0x37, ssa)), kSc);
  EXPECT_EQ(h.slave.address(), 7);
  ASSERT_EQ(h.app.new_addresses, (std::vector<std::uint8_t>{7}));
  EXPECT_TRUE(h.send(sd2({0x85, 0x82, 0x6D, 0x3C, 0x3E})).empty());  // old address silent
  EXPECT_EQ(h.send(sd2({0x87, 0x82, 0x6D, 0x3C, 0x3E})).size(), 17U);
  // Locked now: RS (from address 7).
  EXPECT_EQ(h.send(sd2({0x87, 0x82, 0x5D, 0x37, 0x3E, 0x08, 0x12, 0x34, 0x00})),
            (Bytes{0x10, 0x02, 0x07, 0x03, 0x0C, 0x16}));
  EXPECT_EQ(h.slave.address(), 7);
}

TEST(SlaveSetSlaveAdd, WrongIdentOrAddressIsIgnoredAndDataExchRefuses) {
  SlaveHarness h;
  EXPECT_EQ(h.send(h.dp(0x37, {0x07, 0x43, 0x21, 0x00})), kSc);  // wrong ident
  EXPECT_EQ(h.send(h.dp(0x37, {0x7E, 0x12, 0x34, 0x00})), kSc);  // 126 not allowed
  EXPECT_EQ(h.slave.address(), 5);
  h.to_data_exchange();
  EXPECT_EQ(h.send(h.dp(0x37, {0x07, 0x12, 0x34, 0x00})), kRsTo2);  // only in Wait_Prm
  EXPECT_TRUE(h.app.new_addresses.empty());
}

}  // namespace
}  // namespace rs4sim::dp::testing
