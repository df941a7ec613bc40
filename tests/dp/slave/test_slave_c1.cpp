// MSAC_C1 Read/Write ([IEC 61158-6-3 MSAC_C1]) with the poll pattern on the wire
// ([IEC 61158-6-3 MSAC_C1 polling]), sync and async.
#include "dp/slave/slave_error.h"
#include "tests/dp/slave/slave_harness.h"

namespace rs4sim::dp::testing {
using namespace ::rs4sim::dp::slave;  // the slave under test
namespace {

// Brings the slave into DPV1 Data_Exch and one DX further, so that the next new frame
// from master 2 carries FCB=0 (FC 5C/5D) like the textbook C1 exchange
// ([IEC 61158-6-3 MSAC_C1 polling]).
void to_c1(SlaveHarness& h) {
  h.to_data_exchange();  // 6D, 5D
  h.send(h.dx({0x01}));  // 7D
}

TEST(SlaveC1, ReadExampleFromTheSpec) {
  SlaveHarness h;
  to_c1(h);
  const Bytes read_req{0x68, 0x09, 0x09, 0x68, 0x85, 0x82,
                       0x5C,        // SRD_LO, FCV=1, FCB=0
                       0x33, 0x33,  // DSAP 51 MSAC_C1, SSAP 51
                       0x5E,        // Read
                       0x00,        // slot 0
                       0x01,        // index 1
                       0x10,        // up to 16 bytes
                       0x38, 0x16};
  EXPECT_EQ(h.send(read_req), kSc);  // [IEC 61158-6-3 MSAC_C1 polling] step 2: E5, response not yet
                                     // there
  h.next_fc();                       // keep the harness FCB in step (5C used)
  ASSERT_EQ(h.app.acyclic.size(), 1U);
  EXPECT_EQ(h.app.acyclic[0].req.channel, AcyclicChannel::kC1);
  EXPECT_EQ(h.app.acyclic[0].req.length, 0x10);
  const Bytes poll{0x68, 0x05, 0x05, 0x68, 0x85, 0x82,
                   0x7C,        // FCB toggled
                   0x33, 0x33,  // empty poll
                   0xE9, 0x16};
  h.next_fc();
  EXPECT_EQ(h.send(poll), (Bytes{0x68, 0x0B, 0x0B, 0x68, 0x82, 0x85,
                                 0x08,        // FC DL
                                 0x33, 0x33,  // DSAP 51, SSAP 51
                                 0x5E, 0x00, 0x01,
                                 0x02,        // 2 bytes returned
                                 0xAB, 0xCD,  // data
                                 0x4E, 0x16}));
  EXPECT_EQ(h.send(h.dp(0x33, {}, 0x33)), kSc);  // nothing pending: SC
}

TEST(SlaveC1, NegativeResponseExampleFromTheSpec) {
  SlaveHarness h;
  to_c1(h);
  h.app.acyclic_mode = FakeApplication::AcyclicMode::kError;  // B0 invalid index
  EXPECT_EQ(h.send(h.dp(0x33, {0x5E, 0x00, 0x01, 0x10}, 0x33)), kSc);
  EXPECT_EQ(h.send(h.dp(0x33, {}, 0x33)),
            (Bytes{0x68, 0x09, 0x09, 0x68, 0x82, 0x85, 0x08, 0x33, 0x33,
                   0xDE,  // Read | 0x80
                   0x80,  // Error_Decode DPV1
                   0xB0,  // Error_Code_1 invalid index
                   0x00,  // Error_Code_2
                   0x83, 0x16}));
}

TEST(SlaveC1, MalformedRequestsGetTheDriversImmediateNegatives) {
  SlaveHarness h;
  to_c1(h);
  // Read.req with 5 bytes → DE 80 B3 00; Length 0 → DE 80 B3 00 [VPC3+ dp_msac1.c].
  h.send(h.dp(0x33, {0x5E, 0x00, 0x01, 0x10, 0x00}, 0x33));
  EXPECT_EQ(h.send(h.dp(0x33, {}, 0x33)),
            SlaveHarness::reply(0x08, 0x33, 0x33, {0xDE, 0x80, 0xB3, 0x00}));
  h.send(h.dp(0x33, {0x5E, 0x00, 0x01, 0x00}, 0x33));
  EXPECT_EQ(h.send(h.dp(0x33, {}, 0x33)),
            SlaveHarness::reply(0x08, 0x33, 0x33, {0xDE, 0x80, 0xB3, 0x00}));
  // Write.req Length 0 → DF 80 B3 00; Length ≠ data → DF 80 B3 00 as well.
  h.send(h.dp(0x33, {0x5F, 0x00, 0x02, 0x00}, 0x33));
  EXPECT_EQ(h.send(h.dp(0x33, {}, 0x33)),
            SlaveHarness::reply(0x08, 0x33, 0x33, {0xDF, 0x80, 0xB3, 0x00}));
  h.send(h.dp(0x33, {0x5F, 0x00, 0x02, 0x03, 0x01}, 0x33));
  EXPECT_EQ(h.send(h.dp(0x33, {}, 0x33)),
            SlaveHarness::reply(0x08, 0x33, 0x33, {0xDF, 0x80, 0xB3, 0x00}));
  EXPECT_TRUE(h.app.acyclic.empty());  // none reached the application
  EXPECT_EQ(h.slave.state(), State::kDataExch);
}

TEST(SlaveC1, MoreThanC1MaxDataLenIsRefused) {
  Config cfg = example_config();
  cfg.c1_max_data_length = 2;
  SlaveHarness h(cfg);
  to_c1(h);
  h.send(h.dp(0x33, {0x5E, 0x00, 0x02, 0x03}, 0x33));  // Read 3 > 2
  EXPECT_EQ(h.send(h.dp(0x33, {}, 0x33)),
            SlaveHarness::reply(0x08, 0x33, 0x33, {0xDE, 0x80, 0xB3, 0x00}));
  h.send(h.dp(0x33, {0x5F, 0x00, 0x02, 0x03, 0x01, 0x02, 0x03}, 0x33));  // Write 3 > 2
  EXPECT_EQ(h.send(h.dp(0x33, {}, 0x33)),
            SlaveHarness::reply(0x08, 0x33, 0x33, {0xDF, 0x80, 0xB1, 0x00}));
  EXPECT_TRUE(h.app.acyclic.empty());
}

TEST(SlaveC1, WriteIsAnsweredWithTheHeaderOnly) {
  SlaveHarness h;
  to_c1(h);
  const Bytes write{0x5F, 0x00, 0x02, 0x03, 0x0A, 0x0B, 0x0C};  // slot 0, index 2, 3 bytes
  EXPECT_EQ(h.send(h.dp(0x33, write, 0x33)), kSc);
  ASSERT_EQ(h.app.acyclic.size(), 1U);
  EXPECT_EQ(h.app.acyclic[0].data, (Bytes{0x0A, 0x0B, 0x0C}));
  EXPECT_EQ(h.app.acyclic[0].req.service, AcyclicService::kWrite);
  // A poll that repeats the request PDU is a poll too ([IEC 61158-6-3 MSAC_C1 polling] UNCERTAIN,
  // both accepted).
  EXPECT_EQ(h.send(h.dp(0x33, write, 0x33)),
            SlaveHarness::reply(0x08, 0x33, 0x33, {0x5F, 0x00, 0x02, 0x03}));
  EXPECT_EQ(h.app.acyclic.size(), 1U);
}

TEST(SlaveC1, AsyncCompletionPollsUntilReady) {
  SlaveHarness h;
  to_c1(h);
  h.app.acyclic_mode = FakeApplication::AcyclicMode::kPending;
  EXPECT_EQ(h.send(h.dp(0x33, {0x5E, 0x00, 0x03, 0x08}, 0x33)), kSc);
  EXPECT_EQ(h.send(h.dp(0x33, {}, 0x33)), kSc);
  EXPECT_EQ(h.send(h.dp(0x33, {}, 0x33)), kSc);
  // A different request while busy: RR (no resources, [IEC 61158-6-3 MSAC_C1 polling]).
  EXPECT_EQ(h.send(h.dp(0x33, {0x5E, 0x00, 0x02, 0x08}, 0x33)),
            (Bytes{0x10, 0x02, 0x05, 0x02, 0x09, 0x16}));
  const Bytes data{0x01, 0x02, 0x03};
  ASSERT_FALSE(h.app.control->complete_acyclic(AcyclicChannel::kC1, AcyclicResult::ok(data)));
  EXPECT_EQ(h.app.control->complete_acyclic(AcyclicChannel::kC1, AcyclicResult::ok(data)),
            make_error_code(SlaveError::kNoPendingRequest));
  EXPECT_EQ(h.send(h.dp(0x33, {}, 0x33)),
            SlaveHarness::reply(0x08, 0x33, 0x33, {0x5E, 0x00, 0x03, 0x03, 0x01, 0x02, 0x03}));
}

TEST(SlaveC1, AsyncCompletionLongerThanRequestedIsRefused) {
  SlaveHarness h;
  to_c1(h);
  h.app.acyclic_mode = FakeApplication::AcyclicMode::kPending;
  h.send(h.dp(0x33, {0x5E, 0x00, 0x03, 0x02}, 0x33));
  const Bytes data{0x01, 0x02, 0x03};
  EXPECT_EQ(h.app.control->complete_acyclic(AcyclicChannel::kC1, AcyclicResult::ok(data)),
            make_error_code(SlaveError::kResponseTooLong));
  EXPECT_EQ(h.send(h.dp(0x33, {}, 0x33)), kSc);  // still waiting for a valid answer
}

TEST(SlaveC1, ClosedWithoutDpv1OrForOthers) {
  SlaveHarness h;
  const Bytes rs{0x10, 0x02, 0x05, 0x03, 0x0A, 0x16};
  EXPECT_EQ(h.send(h.dp(0x33, {0x5E, 0x00, 0x01, 0x10}, 0x33)), rs);  // Wait_Prm
  // DPV1_Enable = 0 in Set_Prm: DPV0 mode, SAP 51 stays closed ([IEC 61158-6-3 MSAC_C1]).
  h.to_data_exchange({0x88, 0x0A, 0x01, 0x0B, 0x12, 0x34, 0x00, 0x00, 0x00, 0x00});
  EXPECT_EQ(h.send(h.dp(0x33, {0x5E, 0x00, 0x01, 0x10}, 0x33)), rs);
  EXPECT_EQ(h.send(h.dp(0x3D, SlaveHarness::example_prm())), kSc);
  EXPECT_EQ(h.send(h.dp(0x3E, {0x10, 0x20})), kSc);
  EXPECT_EQ(h.send(h.dp(0x33, {0x5E, 0x00, 0x01, 0x10}, 0x3E)), rs);  // wrong master SAP
  EXPECT_EQ(h.send(sd2({0x85, 0x83, 0x6C, 0x33, 0x33, 0x5E, 0x00, 0x01, 0x10})),
            (Bytes{0x10, 0x03, 0x05, 0x03, 0x0B, 0x16}));  // not the owner
}

TEST(SlaveC1, UnknownFunctionLeavesDataExchange) {
  SlaveHarness h;
  to_c1(h);
  EXPECT_EQ(h.send(h.dp(0x33, {0x57, 0x00, 0x00, 0x00}, 0x33)), kSc);
  EXPECT_EQ(h.slave.state(), State::kWaitPrm);
  EXPECT_EQ(h.app.transitions.back().why, TransitionReason::kProtocolViolation);
}

}  // namespace
}  // namespace rs4sim::dp::testing
