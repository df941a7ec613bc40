// Start-up faults and supervision in data exchange
// ([IEC 61158-6-3 Slave_Diag, Data_Exchange, master start-up of a slave] [pyprofibus dp_master.py],
// [IEC 61158-6-3 slave supervision]): DH → Slave_Diag, Prm_Req → re-parameterisation, RS → restart,
// fault reasons.

#include "master_fixture.h"

#include <gtest/gtest.h>

namespace rs4sim::dp::master::testing {
namespace {

// Slave_Diag reply of slave 5 to master 2 with the six standard bytes.
Bytes diag(std::uint8_t s1, std::uint8_t s2, std::uint8_t master_add,
           std::uint16_t ident = 0x1234) {
  const auto hi = static_cast<std::uint8_t>(ident >> 8);
  const auto lo = static_cast<std::uint8_t>(ident & 0xFF);
  return {0x68,
          0x0B,
          0x0B,
          0x68,
          0x82,
          0x85,  // DA 2, SA 5 (extension bits)
          0x08,  // FC DL
          0x3E,
          0x3C,  // DSAP 62, SSAP 60
          s1,
          s2,
          0x00,
          master_add,
          hi,
          lo,
          fcs({0x82, 0x85, 0x08, 0x3E, 0x3C, s1, s2, 0x00, master_add, hi, lo}),
          0x16};
}
Bytes diag_request(std::uint8_t fc) {
  return {0x68, 0x05, 0x05, 0x68, 0x85, 0x82, fc, 0x3C, 0x3E, fcs({0x85, 0x82, fc, 0x3C, 0x3E}),
          0x16};
}
const Bytes kDxDh = {0x68, 0x04, 0x04, 0x68, 0x02, 0x05,
                     0x0A,  // FC DH: diagnosis pending ([IEC 61158-6-3 Data_Exchange])
                     0x3C, 0x4D, 0x16};
const Bytes kDxDl = {0x68, 0x04, 0x04, 0x68, 0x02, 0x05, 0x08, 0x3C, 0x4B, 0x16};
const Bytes kRs = {0x10, 0x02, 0x05,
                   0x03,  // FC RS: SAP not enabled (slave left DATA_EXCH,
                          // [IEC 61158-6-3 slave state machine] [pyprofibus issue #19 trace])
                   0x0A, 0x16};
const Bytes kRr = {0x10, 0x02, 0x05,
                   0x02,  // FC RR: no resources ([IEC 61158-4-3 frame control])
                   0x09,  // FCS 02+05+02
                   0x16};

std::error_code err(MasterError e) { return make_error_code(e); }

// Runs the start-up up to the diag after Chk_Cfg and answers it with `reply`.
void to_wait_ready(MasterFixture& f, const Bytes& reply) {
  f.step();
  f.reply({0x10, 0x02, 0x05, 0x00, 0x07, 0x16});
  f.step();
  f.reply(diag(0x02, 0x05, 0xFF));
  f.step();
  f.reply({0xE5});
  f.step();
  f.reply({0xE5});
  EXPECT_EQ(hex(f.step()), hex(diag_request(0x5D)));
  f.reply(reply);
}

TEST(MasterSupervision, DataHighFetchesDiagInTheNextSlot) {
  MasterFixture f;
  f.bring_to_dx();
  EXPECT_EQ(f.step()[6], 0x5D);
  f.reply(kDxDh);
  EXPECT_EQ(hex(f.step()), hex(diag_request(0x7D)));  // same turn, right after the DX
  f.reply(diag(0x08, 0x0C, 0x02));                    // Ext_Diag only: stays in DX
  const auto diags = f.events<DiagReceived>();
  ASSERT_EQ(diags.size(), 1U);
  EXPECT_EQ(hex(Bytes(diags[0].diag.begin(), diags[0].diag.end())), "08 0C 00 02 12 34");
  EXPECT_EQ(f.master.slave_status(5)->state, PollState::kDataExchange);
  EXPECT_EQ(f.master.slave_status(5)->counters.diag_reads, 3U);
  // Next cycle: only the Data_Exchange (FCB=0 again), no diag.
  EXPECT_EQ(f.step()[6], 0x5D);
  f.reply(kDxDl);
  f.step();
  EXPECT_EQ(f.master.slave_status(5)->counters.diag_reads, 3U);
}

TEST(MasterSupervision, PrmReqInDataExchangeReparameterises) {
  MasterFixture f;
  f.bring_to_dx();
  f.step();
  f.reply(kDxDh);
  f.step();
  f.reply(diag(0x02, 0x05, 0xFF));  // watchdog fired: Not_Ready, Prm_Req, no master
  const auto left = f.events<SlaveLeftDataExchange>();
  ASSERT_EQ(left.size(), 1U);
  EXPECT_EQ(left[0].reason, err(MasterError::kLeftDataExchange));
  // Next cycle starts again at Set_Prm ([IEC 61158-6-3 master start-up of a slave]
  // [pyprofibus dp_master.py] "Prm_Req → restart at 2"), FCB toggled.
  const Bytes prm = f.step();
  ASSERT_GT(prm.size(), 9U);
  EXPECT_EQ(prm[6], 0x5D);
  EXPECT_EQ(prm[7], 0x3D) << "DSAP 61 Set_Prm";
  EXPECT_EQ(f.master.slave_status(5)->state, PollState::kSetPrm);
}

TEST(MasterSupervision, RsToDataExchangeRestartsAtSlaveDiag) {
  MasterFixture f;
  f.bring_to_dx();
  f.step();
  f.reply(kRs);
  const auto left = f.events<SlaveLeftDataExchange>();
  ASSERT_EQ(left.size(), 1U);
  EXPECT_EQ(left[0].reason, err(MasterError::kSapNotEnabled));
  EXPECT_EQ(hex(f.step()), hex(diag_request(0x7D)));
  // ProfiTrace's live list: one RS/RR negative reply and one Lost; a negative reply is not
  // counted as Illegal too (the two columns count apart)
  const auto c = f.master.slave_status(5)->counters;
  EXPECT_EQ(c.negative_replies, 1U);
  EXPECT_EQ(c.left_data_exchange, 1U);
  EXPECT_EQ(c.entered_data_exchange, 1U);
  EXPECT_EQ(c.invalid_responses, 0U);
  EXPECT_EQ(c.retries, 0U);
}

TEST(MasterSupervision, RrToDataExchangeCountsANegativeReply) {
  MasterFixture f;
  f.bring_to_dx();
  f.step();
  f.reply(kRr);
  ASSERT_EQ(f.events<SlaveLeftDataExchange>().size(), 1U);
  EXPECT_EQ(f.master.slave_status(5)->counters.negative_replies, 1U);
  f.step();
  f.reply(kDxDl);  // a positive reply (out of place here) is no negative one
  EXPECT_EQ(f.master.slave_status(5)->counters.negative_replies, 1U);
}

TEST(MasterSupervision, InputLengthMismatchLeavesDataExchange) {
  MasterFixture f;
  f.bring_to_dx();
  f.step();
  f.reply({0x68, 0x05, 0x05, 0x68, 0x02, 0x05, 0x08, 0x3C, 0x3D,
           fcs({0x02, 0x05, 0x08, 0x3C, 0x3D}), 0x16});  // two input bytes, one configured
  const auto left = f.events<SlaveLeftDataExchange>();
  ASSERT_EQ(left.size(), 1U);
  EXPECT_EQ(left[0].reason, err(MasterError::kInputLengthMismatch));
  EXPECT_EQ(f.master.slave_status(5)->counters.invalid_responses, 1U);
}

TEST(MasterSupervision, StatDiagKeepsFetchingEveryCycle) {
  MasterFixture f;
  f.bring_to_dx();
  f.step();
  f.reply(kDxDh);
  f.step();
  f.reply(diag(0x00, 0x0E, 0x02));  // Stat_Diag (bit 1) set
  f.step();                         // next cycle DX
  f.reply(kDxDl);                   // DL: no new diag flag …
  EXPECT_EQ(f.step()[7], 0x3C) << "… but Stat_Diag still requires a Slave_Diag";
}

TEST(MasterSupervision, StartupFaultReasons) {
  struct Case {
    Bytes reply;
    MasterError reason;
  };
  const Case cases[] = {
      {diag(0x40, 0x0C, 0x02), MasterError::kPrmFault},      // Station_Status_1 bit 6
      {diag(0x04, 0x0C, 0x02), MasterError::kCfgFault},      // bit 2
      {diag(0x10, 0x0C, 0x02), MasterError::kNotSupported},  // bit 4
      {diag(0x00, 0x0C, 0x07), MasterError::kMasterLock},    // Master_Add 7
      {diag(0x00, 0x0C, 0x02, 0x4711), MasterError::kIdentMismatch},
  };
  for (const Case& c : cases) {
    MasterFixture f;
    to_wait_ready(f, c.reply);
    const auto faults = f.events<SlaveFault>();
    ASSERT_EQ(faults.size(), 1U) << hex(c.reply);
    EXPECT_EQ(faults[0].reason, err(c.reason)) << hex(c.reply);
    EXPECT_EQ(f.master.slave_status(5)->state, PollState::kReadDiag) << hex(c.reply);
    EXPECT_TRUE(f.events<SlaveEnteredDataExchange>().empty());
  }
}

TEST(MasterSupervision, PrmReqAfterChkCfgRepeatsSetPrm) {
  MasterFixture f;
  to_wait_ready(f, diag(0x02, 0x05, 0xFF));
  EXPECT_EQ(f.master.slave_status(5)->state, PollState::kSetPrm);
  EXPECT_EQ(f.step()[7], 0x3D);
}

TEST(MasterSupervision, FirstDiagChecksIdentAndMasterLock) {
  MasterFixture f;
  f.step();
  f.reply({0x10, 0x02, 0x05, 0x00, 0x07, 0x16});
  f.step();
  f.reply(diag(0x82, 0x04, 0x09));  // parameterised by master 9
  EXPECT_EQ(f.events<SlaveFault>().at(0).reason, err(MasterError::kMasterLock));
  EXPECT_EQ(f.master.slave_status(5)->state, PollState::kReadDiag);
  f.step();
  f.reply(diag(0x02, 0x05, 0xFF, 0x9999));
  EXPECT_EQ(f.events<SlaveFault>().at(0).reason, err(MasterError::kIdentMismatch));
}

TEST(MasterSupervision, FdlStatusFromAMasterIsNotASlave) {
  MasterFixture f;
  f.step();
  f.reply({0x10, 0x02, 0x05,
           0x20,  // FC: station type "master ready, no token", status OK
           fcs({0x02, 0x05, 0x20}), 0x16});
  EXPECT_EQ(f.events<SlaveFault>().at(0).reason, err(MasterError::kNotASlave));
  EXPECT_EQ(f.master.slave_status(5)->state, PollState::kStatusRequest);
}

TEST(MasterSupervision, SetPrmRejectedWithRsRestarts) {
  MasterFixture f;
  f.step();
  f.reply({0x10, 0x02, 0x05, 0x00, 0x07, 0x16});
  f.step();
  f.reply(diag(0x02, 0x05, 0xFF));
  f.step();
  f.reply(kRs);
  EXPECT_EQ(f.events<SlaveFault>().at(0).reason, err(MasterError::kSapNotEnabled));
  EXPECT_EQ(f.master.slave_status(5)->state, PollState::kReadDiag);
}

TEST(MasterSupervision, ReadyTimeoutRestartsAtSlaveDiag) {
  MasterConfig cfg = example_master();
  cfg.ready_timeout = std::chrono::milliseconds(25);
  MasterFixture f(cfg);
  to_wait_ready(f, diag(0x02, 0x0C, 0x02));  // not ready
  for (int cycle = 0; cycle < 2; ++cycle) {
    f.step();
    f.reply(diag(0x02, 0x0C, 0x02));
  }
  EXPECT_TRUE(f.events<SlaveFault>().empty());
  f.step();  // third cycle ≥ 25 ms after Chk_Cfg
  EXPECT_EQ(f.events<SlaveFault>().at(0).reason, err(MasterError::kStartupTimeout));
  EXPECT_EQ(f.master.slave_status(5)->state, PollState::kReadDiag);
}

}  // namespace
}  // namespace rs4sim::dp::master::testing
