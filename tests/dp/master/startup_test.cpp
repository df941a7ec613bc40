// Per-slave start-up of the class 1 master, byte for byte against the worked example of
// [docs/references.md#dp-worked-example] (master 2, slave 5, ident 0x1234) and the table of
// [IEC 61158-6-3 master start-up of a slave] [pyprofibus dp_master.py].

#include "master_fixture.h"

#include <gtest/gtest.h>

namespace rs4sim::dp::master::testing {
namespace {

// --- Requests of the master ([docs/references.md#dp-worked-example]) ---
const Bytes kFdlStatusReq = {
    0x10,  // 0 SD1
    0x05,  // 1 DA slave 5
    0x02,  // 2 SA master 2
    0x49,  // 3 FC request FDL status, FCV=0 FCB=0
    0x50,  // 4 FCS
    0x16,  // 5 ED
};
const Bytes kDiagFirstReq = {
    0x68, 0x05, 0x05, 0x68,  // 0..3 SD2, LE=LEr=5
    0x85,                    // 4 DA 5 | extension bit
    0x82,                    // 5 SA 2 | extension bit
    0x6D,                    // 6 FC SRD high, FCB=1 FCV=0 (first frame, [IEC 61158-4-3 FCB/FCV])
    0x3C,                    // 7 DSAP 60 Slave_Diag
    0x3E,                    // 8 SSAP 62 master MS0
    0xEE, 0x16,              // 9 FCS, 10 ED
};
const Bytes kSetPrmReq = {
    0x68, 0x0F, 0x0F, 0x68,  // 0..3 SD2, LE=15
    0x85, 0x82,              // 4 DA 5, 5 SA 2
    0x5D,                    // 6 FC SRD high, FCV=1 FCB=0
    0x3D, 0x3E,              // 7 DSAP 61 Set_Prm, 8 SSAP 62
    0x88,                    // 9  Station_Status: Lock_Req + WD_On
    0x0A, 0x01,              // 10 WD_Fact_1 10, 11 WD_Fact_2 1 (100 ms)
    0x0B,                    // 12 min TSDR 11
    0x12, 0x34,              // 13..14 Ident_Number 0x1234
    0x00,                    // 15 Group_Ident
    0x80, 0x20, 0x00,        // 16..18 DPV1_Status_1..3: DPV1_Enable, diag alarm, mode 0
    0x63, 0x16,              // 19 FCS, 20 ED
};
const Bytes kChkCfgReq = {
    0x68, 0x07, 0x07, 0x68,  // SD2, LE=7
    0x85, 0x82,              // DA 5, SA 2
    0x7D,                    // 6 FC SRD high, FCV=1 FCB=1
    0x3E, 0x3E,              // 7 DSAP 62 Chk_Cfg, 8 SSAP 62
    0x10, 0x20,              // 9 1 byte input, 10 1 byte output
    0x30, 0x16,              // FCS, ED
};
const Bytes kDiagReq5D = {0x68, 0x05, 0x05, 0x68, 0x85, 0x82,
                          0x5D,  // FC SRD high, FCV=1 FCB=0
                          0x3C, 0x3E, 0xDE, 0x16};
const Bytes kDxReq7D = {
    0x68, 0x04, 0x04, 0x68,  // SD2, LE=4
    0x05, 0x02,              // DA 5, SA 2 (no extension: default SAP = Data_Exchange)
    0x7D,                    // FC SRD high, FCV=1 FCB=1
    0xA5,                    // output byte
    0x29, 0x16,              // FCS, ED
};

// --- Replies of the slave ([docs/references.md#dp-worked-example]) ---
const Bytes kFdlStatusRes = {0x10, 0x02, 0x05,
                             0x00,  // FC: station type slave, status OK
                             0x07, 0x16};
const Bytes kDiagWaitPrm = {0x68, 0x0B, 0x0B, 0x68, 0x82, 0x85,
                            0x08,        // FC DL
                            0x3E, 0x3C,  // DSAP 62, SSAP 60
                            0x02,        // Station_Status_1: Station_Not_Ready
                            0x05,        // Station_Status_2: Prm_Req + always-1
                            0x00,        // Station_Status_3
                            0xFF,        // Master_Add: not parameterised
                            0x12, 0x34,  // Ident
                            0xD5, 0x16};
const Bytes kDiagReady = {0x68, 0x0B, 0x0B, 0x68, 0x82, 0x85, 0x08, 0x3E, 0x3C,
                          0x00,  // Station_Status_1: ready
                          0x0C,  // Station_Status_2: WD_On + always-1
                          0x00,
                          0x02,  // Master_Add 2
                          0x12, 0x34, 0xDD, 0x16};
const Bytes kSc = {0xE5};
const Bytes kDxResDl = {0x68, 0x04, 0x04, 0x68, 0x02, 0x05,
                        0x08,  // FC DL
                        0x3C,  // input byte
                        0x4B, 0x16};

TEST(MasterStartup, WorkedExampleByteForByte) {
  MasterFixture f;
  ASSERT_FALSE(f.master.set_outputs(5, Bytes{0xA5}));
  EXPECT_EQ(hex(f.step()), hex(kFdlStatusReq));
  f.reply(kFdlStatusRes);
  EXPECT_EQ(hex(f.step()), hex(kDiagFirstReq));
  f.reply(kDiagWaitPrm);
  EXPECT_EQ(hex(f.step()), hex(kSetPrmReq));
  f.reply(kSc);
  EXPECT_EQ(hex(f.step()), hex(kChkCfgReq));
  f.reply(kSc);
  EXPECT_EQ(hex(f.step()), hex(kDiagReq5D));
  f.reply(kDiagReady);
  EXPECT_EQ(f.events<SlaveEnteredDataExchange>().size(), 1U);
  EXPECT_EQ(hex(f.step()), hex(kDxReq7D));
  f.reply(kDxResDl);
  ASSERT_EQ(f.master.inputs(5).size(), 1U);
  EXPECT_EQ(f.master.inputs(5)[0], 0x3C);
  const auto st = f.master.slave_status(5);
  ASSERT_TRUE(st);
  EXPECT_STREQ(st->state_name, "DataExchange");
  EXPECT_EQ(st->counters.data_exchanges, 1U);
  EXPECT_EQ(st->counters.requests, 6U);  // FDL_Status, Diag, Prm, Cfg, Diag, DX
}

TEST(MasterStartup, NextRequestWaitsTid1AfterReply) {
  MasterFixture f;
  f.step();
  const TimePoint t_reply = f.clock.now() + std::chrono::microseconds(50);
  f.clock.set(t_reply);
  f.reply(kFdlStatusRes);
  // TID1 = 37 bit at 1.5 Mbit/s = 24.67 µs ([IEC 61158-4-3 bus parameters, timing]
  // [COM PROFIBUS bus-parameter printout]).
  EXPECT_TRUE(f.poke().empty());
  f.clock.set(t_reply + std::chrono::nanoseconds(24'600));
  EXPECT_TRUE(f.poke().empty());
  f.clock.set(t_reply + std::chrono::nanoseconds(24'700));
  EXPECT_EQ(hex(f.poke()), hex(kDiagFirstReq));
}

TEST(MasterStartup, OnALinkThatHonoursSendTimesTheNextRequestComesWithTheReplyDueTid1Later) {
  MasterFixture f;
  f.master.set_send_time_honoured(true);
  f.step();
  EXPECT_FALSE(f.master.send_time());  // built by on_time(): due at once
  const TimePoint t_reply = f.clock.now() + std::chrono::microseconds(50);
  f.clock.set(t_reply);
  f.reply(kFdlStatusRes);
  // Handed out now, with the send time reply + TID1 (37 bit at 1.5 Mbit/s = 24.67 µs): the same
  // request and the same instant on the wire as NextRequestWaitsTid1AfterReply.
  EXPECT_EQ(hex(f.drain()), hex(kDiagFirstReq));
  const auto at = f.master.send_time();
  ASSERT_TRUE(at);
  EXPECT_GT(*at, t_reply + std::chrono::nanoseconds(24'600));
  EXPECT_LE(*at, t_reply + std::chrono::nanoseconds(24'700));
  // Its slot time runs from the send time, not from the reply.
  const auto deadline = f.master.next_deadline();
  ASSERT_TRUE(deadline);
  EXPECT_GT(*deadline, *at);
  f.clock.set(*at);
  EXPECT_TRUE(f.poke().empty());  // no second copy when the send time comes
}

TEST(MasterStartup, NotReadyDiagWaitsForTheNextCycle) {
  MasterFixture f;
  f.step();
  f.reply(kFdlStatusRes);
  f.step();
  f.reply(kDiagWaitPrm);
  f.step();
  f.reply(kSc);
  f.step();
  f.reply(kSc);
  EXPECT_EQ(hex(f.step()), hex(kDiagReq5D));
  // Parameterised but Station_Not_Ready still set (ET200S trace `02 0C 00 02`).
  f.reply({0x68, 0x0B, 0x0B, 0x68, 0x82, 0x85, 0x08, 0x3E, 0x3C, 0x02, 0x0C, 0x00, 0x02, 0x12, 0x34,
           fcs({0x82, 0x85, 0x08, 0x3E, 0x3C, 0x02, 0x0C, 0x00, 0x02, 0x12, 0x34}), 0x16});
  const TimePoint after = f.clock.now();
  // Next request is the next cycle's Slave_Diag, 10 ms after the first cycle began.
  const Bytes next = f.step();
  EXPECT_EQ(hex(next), hex(Bytes{0x68, 0x05, 0x05, 0x68, 0x85, 0x82, 0x7D, 0x3C, 0x3E,
                                 fcs({0x85, 0x82, 0x7D, 0x3C, 0x3E}), 0x16}));
  EXPECT_GT(f.clock.now() - after, std::chrono::milliseconds(9));
  EXPECT_EQ(f.master.slave_status(5)->state, PollState::kWaitReady);
}

TEST(MasterStartup, WithoutFdlStatusStartsWithSlaveDiag) {
  MasterConfig cfg = example_master();
  cfg.fdl_status_first = false;
  MasterFixture f(cfg);
  EXPECT_EQ(hex(f.step()), hex(kDiagFirstReq));
}

TEST(MasterStartup, ClaimsTokenAfterTtoOfSilence) {
  MasterConfig cfg = example_master();
  cfg.claim_token = true;
  MasterFixture f(cfg);
  EXPECT_TRUE(f.poke().empty());
  EXPECT_EQ(f.master.phase(), MasterPhase::kListening);
  // TTO = TSL·(6 + 2·TS) = 300·10 = 3000 bit = 2 ms at 1.5 Mbit/s
  // ([IEC 61158-4-3 bus parameters, timing]).
  const TimePoint t0 = f.clock.now();
  f.clock.set(t0 + std::chrono::microseconds(1999));
  EXPECT_TRUE(f.poke().empty());
  f.clock.set(t0 + std::chrono::microseconds(2000));
  EXPECT_EQ(hex(f.poke()), "DC 02 02");  // token to itself ([IEC 61158-4-3 token])
  EXPECT_EQ(hex(f.step()), "DC 02 02");  // again, TSYN later
  EXPECT_EQ(f.master.phase(), MasterPhase::kRunning);
  EXPECT_EQ(hex(f.step()), hex(kFdlStatusReq));
}

TEST(MasterStartup, TrafficWhileListeningRestartsTheWait) {
  MasterConfig cfg = example_master();
  cfg.claim_token = true;
  MasterFixture f(cfg);
  f.poke();
  f.clock.advance(std::chrono::microseconds(1500));
  f.reply({0xDC, 0x09, 0x07});  // another master passes the token
  f.clock.advance(std::chrono::microseconds(1500));
  EXPECT_TRUE(f.poke().empty());
  EXPECT_EQ(f.master.phase(), MasterPhase::kListening);
  f.clock.advance(std::chrono::microseconds(500));
  EXPECT_EQ(hex(f.poke()), "DC 02 02");
}

}  // namespace
}  // namespace rs4sim::dp::master::testing
