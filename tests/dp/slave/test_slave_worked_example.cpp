// [docs/references.md#dp-worked-example] worked example (master 2, slave 5, ident 0x1234), byte for
// byte: every request and every expected reply below is copied from there.
#include "tests/dp/slave/slave_harness.h"

#include <chrono>
#include <string>

namespace rs4sim::dp::testing {
using namespace ::rs4sim::dp::slave;  // the slave under test
namespace {

TEST(SlaveWorkedExample, FullStartUpAndCycle) {
  SlaveHarness h;
  // FDL_Status request
  const Bytes fdl_status{
      0x10,  // 0 SD1
      0x05,  // 1 DA slave 5
      0x02,  // 2 SA master 2
      0x49,  // 3 FC request FDL status (no FCB)
      0x50,  // 4 FCS
      0x16,  // 5 ED
  };
  EXPECT_EQ(h.send(fdl_status), (Bytes{0x10, 0x02, 0x05, 0x00, 0x07, 0x16}));  // FC 00 slave OK

  // First Slave_Diag, FCB=1 FCV=0
  const Bytes diag1{
      0x68, 0x05, 0x05, 0x68,  // 0..3 SD2, LE=LEr=5
      0x85,                    // 4 DA 5 + extension
      0x82,                    // 5 SA 2 + extension
      0x6D,                    // 6 FC SRD_HI, FCB=1, FCV=0 (first frame)
      0x3C,                    // 7 DSAP 60 Slave_Diag
      0x3E,                    // 8 SSAP 62
      0xEE, 0x16,              // 9 FCS, 10 ED
  };
  const Bytes diag1_reply{
      0x68, 0x0B, 0x0B, 0x68,  // SD2, LE 11
      0x82, 0x85,              // DA 2, SA 5 (+ext)
      0x08,                    // FC DL
      0x3E, 0x3C,              // DSAP 62, SSAP 60 (swapped)
      0x02,                    // Station_Status_1: Station_Not_Ready
      0x05,                    // Station_Status_2: Prm_Req + bit 2
      0x00,                    // Station_Status_3
      0xFF,                    // Master_Add: not parameterised
      0x12, 0x34,              // Ident_Number
      0xD5, 0x16,
  };
  EXPECT_EQ(h.send(diag1), diag1_reply);

  const Bytes set_prm{
      0x68, 0x0F, 0x0F, 0x68, 0x85, 0x82,
      0x5D,              // FC SRD_HI, FCV=1, FCB=0
      0x3D, 0x3E,        // DSAP 61 Set_Prm, SSAP 62
      0x88,              // Station_Status: Lock_Req + WD_On
      0x0A, 0x01,        // WD_Fact_1 10, WD_Fact_2 1 → 100 ms
      0x0B,              // min TSDR 11
      0x12, 0x34,        // Ident_Number
      0x00,              // Group_Ident
      0x80, 0x20, 0x00,  // DPV1_Status_1..3: DPV1_Enable, diag alarm enable, alarm mode 0
      0x63, 0x16,
  };
  EXPECT_EQ(h.send(set_prm), kSc);
  EXPECT_EQ(h.slave.state(), State::kWaitCfg);

  const Bytes chk_cfg{0x68, 0x07, 0x07, 0x68, 0x85, 0x82,
                      0x7D,        // FC FCV=1, FCB=1
                      0x3E, 0x3E,  // DSAP 62 Chk_Cfg, SSAP 62
                      0x10,        // 1 byte input
                      0x20,        // 1 byte output
                      0x30, 0x16};
  EXPECT_EQ(h.send(chk_cfg), kSc);
  EXPECT_EQ(h.slave.state(), State::kDataExch);

  const Bytes diag2{0x68, 0x05, 0x05, 0x68, 0x85, 0x82, 0x5D, 0x3C, 0x3E, 0xDE, 0x16};
  const Bytes diag2_reply{0x68, 0x0B, 0x0B, 0x68, 0x82, 0x85, 0x08, 0x3E, 0x3C,
                          0x00,  // Station_Status_1: ready
                          0x0C,  // Station_Status_2: WD_On + bit 2
                          0x00,
                          0x02,  // Master_Add 2
                          0x12, 0x34, 0xDD, 0x16};
  EXPECT_EQ(h.send(diag2), diag2_reply);

  const Bytes dx{0x68, 0x04, 0x04, 0x68, 0x05, 0x02,  // DA 5, SA 2, no extension = default SAP
                 0x7D,                                // FC SRD_HI FCV=1 FCB=1
                 0xA5,                                // output byte
                 0x29, 0x16};
  h.app.inputs = {0x3C};
  EXPECT_EQ(h.send(dx), (Bytes{0x68, 0x04, 0x04, 0x68, 0x02, 0x05,
                               0x08,  // FC DL
                               0x3C,  // input byte
                               0x4B, 0x16}));
  ASSERT_EQ(h.app.outputs.size(), 1U);
  EXPECT_EQ(h.app.outputs[0], Bytes{0xA5});

  // New device diagnosis pending → the same DX is answered DH ([IEC 61158-6-3 Data_Exchange]).
  ASSERT_FALSE(
      h.app.control->set_device_diagnosis(Bytes{0x05, 0x81, 0x00, 0x00, 0x00}, false, false));
  const Bytes dx2{0x68, 0x04, 0x04, 0x68, 0x05, 0x02, 0x5D, 0xA5, 0x09, 0x16};  // FCB toggled
  EXPECT_EQ(h.send(dx2), (Bytes{0x68, 0x04, 0x04, 0x68, 0x02, 0x05, 0x0A, 0x3C, 0x4D, 0x16}));

  // Global_Control Clear to all (DA 127, SDN): never answered, outputs cleared
  // ([IEC 61158-6-3 Global_Control]).
  const Bytes gc_clear{0x68, 0x07, 0x07, 0x68,
                       0xFF,  // DA 127 + extension
                       0x82,  // SA 2 + extension
                       0x46,  // FC SDN high
                       0x3A,  // DSAP 58 Global_Control
                       0x3E,  // SSAP 62
                       0x02,  // Control_Command: Clear_Data
                       0x00,  // Group_Select: all
                       0x41, 0x16};
  EXPECT_TRUE(h.send(gc_clear).empty());
  ASSERT_EQ(h.app.clears.size(), 1U);
  EXPECT_EQ(h.app.clears[0], OutputClear::kGlobalControlClear);
}

TEST(SlaveWorkedExample, DataExchangeOutsideDataExchIsRs) {
  SlaveHarness h;
  const Bytes dx{0x68, 0x04, 0x04, 0x68, 0x05, 0x02, 0x7D, 0xA5, 0x29, 0x16};
  // [docs/references.md#dp-worked-example] "RS (not in DX)": SD1, DA 2, SA 5, FC 03.
  EXPECT_EQ(h.send(dx), (Bytes{0x10, 0x02, 0x05, 0x03, 0x0A, 0x16}));
  EXPECT_TRUE(h.app.outputs.empty());
  EXPECT_EQ(h.slave.counters().rs_replies, 1U);
}

TEST(SlaveWorkedExample, TransitionsAreReportedByStateName) {
  SlaveHarness h;
  std::vector<std::string> log;
  h.slave.set_trace([&](const Transition& tr) {
    log.push_back(std::string(to_string(tr.from)) + "->" + to_string(tr.to));
  });
  h.to_data_exchange();
  EXPECT_EQ(log, (std::vector<std::string>{"Wait_Prm->Wait_Cfg", "Wait_Cfg->Data_Exch"}));
  ASSERT_EQ(h.app.transitions.size(), 2U);
  EXPECT_EQ(h.app.transitions[1].why, TransitionReason::kCfgAccepted);
}

TEST(SlaveWorkedExample, Et200sTraceSetPrmShape) {
  // [pyprofibus issue #26 trace] ([docs/references.md#dp-worked-example]): DPV0 Set_Prm `B8 1E 01
  // 00 80 6A 01`, diag after it `02 0C 00 02`.
  Config cfg = example_config();
  cfg.dpv1 = false;
  cfg.ident_number = 0x806A;
  SlaveHarness h(cfg);
  EXPECT_EQ(h.diag(), (Bytes{0x02, 0x05, 0x00, 0xFF, 0x80, 0x6A}));  // power-up, as traced
  const Bytes prm{0xB8,        // Lock_Req + Sync_Req + Freeze_Req + WD_On
                  0x1E, 0x01,  // WD_Fact 30 · 1 → 300 ms
                  0x00,        // min TSDR 0 = unchanged
                  0x80, 0x6A,  // Ident_Number
                  0x01};       // Group_Ident: group 1
  EXPECT_EQ(h.send(h.dp(0x3D, prm)), kSc);
  EXPECT_EQ(h.slave.state(), State::kWaitCfg);
  EXPECT_EQ(h.slave.watchdog_time(), Duration(std::chrono::milliseconds(300)));
  EXPECT_EQ(h.slave.min_tsdr(), 11);
  EXPECT_EQ(h.diag(), (Bytes{0x02, 0x0C, 0x00, 0x02, 0x80, 0x6A}));
}

}  // namespace
}  // namespace rs4sim::dp::testing
