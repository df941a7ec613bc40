// DPV1 MSAC_C1 client of the master ([IEC 61158-6-3 MSAC_C1, MSAC_C1 polling]): request, polling
// until the response, negative responses, timeout and no-answer as distinct errors.

#include "master_fixture.h"

#include <gtest/gtest.h>

namespace rs4sim::dp::master::testing {
namespace {

const Bytes kDxDl = {0x68, 0x04, 0x04, 0x68, 0x02, 0x05, 0x08, 0x3C, 0x4B, 0x16};

// Runs one cycle's Data_Exchange (FCB 0 in the first call after bring_to_dx) and returns
// the telegram that follows it in the same turn.
Bytes after_dx(MasterFixture& f) {
  f.step();
  f.reply(kDxDl);
  return f.step();
}

TEST(MasterDpv1, ReadPollsUntilTheResponse) {
  MasterFixture f;
  f.bring_to_dx();
  const auto id = f.master.read(5, 0, 1, 16);
  ASSERT_TRUE(id) << id.error().message();
  // Read.req after the DX (5D) of this turn, SRD low with FCB=1 ([IEC 61158-6-3 MSAC_C1 polling]
  // example, FC 7C).
  EXPECT_EQ(hex(after_dx(f)),
            hex(Bytes{0x68, 0x09, 0x09, 0x68,  // SD2, LE 9
                      0x85, 0x82,              // DA 5, SA 2 (extension bits)
                      0x7C,                    // SRD low, FCV=1, FCB=1
                      0x33, 0x33,              // DSAP 51 MSAC_C1, SSAP 51
                      0x5E,                    // Read.req
                      0x00,                    // slot 0
                      0x01,                    // index 1
                      0x10,                    // length 16
                      fcs({0x85, 0x82, 0x7C, 0x33, 0x33, 0x5E, 0x00, 0x01, 0x10}), 0x16}));
  f.reply({0xE5});  // no response yet ([IEC 61158-6-3 MSAC_C1 polling] step 2)
  EXPECT_TRUE(f.events<Dpv1Result>().empty());
  // Next cycle: DX (FCB 0), then an empty poll on SAP 51 (FCB 1).
  f.step();
  f.reply(kDxDl);
  EXPECT_EQ(f.step(), Bytes({0x68, 0x05, 0x05, 0x68, 0x85, 0x82, 0x7C, 0x33, 0x33,
                             fcs({0x85, 0x82, 0x7C, 0x33, 0x33}), 0x16}));
  // Read.res+ from the [IEC 61158-6-3 MSAC_C1 polling] example: 2 bytes AB CD.
  f.reply({0x68, 0x0B, 0x0B, 0x68, 0x82, 0x85, 0x08, 0x33, 0x33, 0x5E, 0x00, 0x01, 0x02, 0xAB, 0xCD,
           0x4E, 0x16});
  const auto results = f.events<Dpv1Result>();
  ASSERT_EQ(results.size(), 1U);
  EXPECT_EQ(results[0].id, id.value());
  EXPECT_FALSE(results[0].error) << results[0].error.message();
  EXPECT_EQ(results[0].operation, Dpv1Operation::kRead);
  EXPECT_EQ(hex(Bytes(results[0].data.begin(), results[0].data.end())), "AB CD");
}

TEST(MasterDpv1, WriteAnsweredAtOnce) {
  MasterFixture f;
  f.bring_to_dx();
  const auto id = f.master.write(5, 1, 2, Bytes{0x11, 0x22, 0x33});
  ASSERT_TRUE(id);
  EXPECT_EQ(hex(after_dx(f)),
            hex(Bytes{0x68, 0x0C, 0x0C, 0x68, 0x85, 0x82, 0x7C, 0x33, 0x33,
                      0x5F,              // Write.req
                      0x01, 0x02, 0x03,  // slot 1, index 2, length 3
                      0x11, 0x22, 0x33,  // data
                      fcs({0x85, 0x82, 0x7C, 0x33, 0x33, 0x5F, 0x01, 0x02, 0x03, 0x11, 0x22, 0x33}),
                      0x16}));
  // Write.res+ `5F 01 02 03` in the reply to the request itself (masters accept both).
  f.reply({0x68, 0x09, 0x09, 0x68, 0x82, 0x85, 0x08, 0x33, 0x33, 0x5F, 0x01, 0x02, 0x03,
           fcs({0x82, 0x85, 0x08, 0x33, 0x33, 0x5F, 0x01, 0x02, 0x03}), 0x16});
  const auto r = f.events<Dpv1Result>();
  ASSERT_EQ(r.size(), 1U);
  EXPECT_FALSE(r[0].error);
  EXPECT_EQ(r[0].length, 3);
  EXPECT_EQ(r[0].operation, Dpv1Operation::kWrite);
}

TEST(MasterDpv1, NegativeResponseMapsToTypedError) {
  MasterFixture f;
  f.bring_to_dx();
  ASSERT_TRUE(f.master.read(5, 0, 1, 16));
  after_dx(f);
  // [IEC 61158-6-3 MSAC_C1 polling] negative example: DE 80 B0 00 = Read, DPV1, access/invalid
  // index.
  f.reply({0x68, 0x09, 0x09, 0x68, 0x82, 0x85, 0x08, 0x33, 0x33,
           0xDE,  // Read | 0x80
           0x80,  // Error_Decode DPV1
           0xB0,  // Error_Code_1: class B access, code 0 invalid index
           0x00,  // Error_Code_2
           0x83, 0x16});
  const auto r = f.events<Dpv1Result>();
  ASSERT_EQ(r.size(), 1U);
  EXPECT_EQ(r[0].error.category(), dpv1_error_category());
  EXPECT_EQ(r[0].error.value(), 0xB0);
  EXPECT_NE(r[0].error.message().find("invalid index"), std::string::npos);
  EXPECT_NE(r[0].error.message().find("access"), std::string::npos);
  ASSERT_TRUE(r[0].negative);
  EXPECT_EQ(r[0].negative->error_decode, 0x80);
  EXPECT_EQ(pdu::to_wire(r[0].negative->error_code_1), 0xB0);
  EXPECT_EQ(r[0].negative->error_code_2, 0x00);
}

TEST(MasterDpv1, NonDpv1ErrorDecodeIsKeptVerbatim) {
  MasterFixture f;
  f.bring_to_dx();
  ASSERT_TRUE(f.master.write(5, 0, 3, Bytes{0x01}));
  after_dx(f);
  f.reply({0x68, 0x09, 0x09, 0x68, 0x82, 0x85, 0x08, 0x33, 0x33, 0xDF, 0xFE, 0x12,
           0x34,  // Write | 0x80, Error_Decode FMS, codes 12 34
           fcs({0x82, 0x85, 0x08, 0x33, 0x33, 0xDF, 0xFE, 0x12, 0x34}), 0x16});
  const auto r = f.events<Dpv1Result>();
  ASSERT_EQ(r.size(), 1U);
  EXPECT_EQ(r[0].error, make_error_code(MasterError::kDpv1Negative));
  EXPECT_EQ(r[0].negative->error_decode, 0xFE);
  EXPECT_EQ(r[0].negative->error_code_2, 0x34);
}

TEST(MasterDpv1, TimeoutResultCarriesTheTimeoutError) {
  MasterConfig cfg = example_master();
  cfg.slaves[0].c1_response_timeout = std::chrono::milliseconds(15);
  MasterFixture f(cfg);
  f.bring_to_dx();
  ASSERT_TRUE(f.master.read(5, 0, 1, 4));
  after_dx(f);
  f.reply({0xE5});
  after_dx(f);  // poll at +10 ms
  f.reply({0xE5});
  const TimePoint before = f.clock.now();
  EXPECT_TRUE(f.events<Dpv1Result>().empty()) << "10 ms < 15 ms: still polling";
  const Bytes dx = f.step();  // cycle at +20 ms: the timeout is found at the cycle start
  EXPECT_EQ(dx[4], 0x05) << "a Data_Exchange (no SAP extension), not a poll";
  EXPECT_LT(f.clock.now() - before, std::chrono::milliseconds(10));
  const auto r = f.events<Dpv1Result>();
  ASSERT_EQ(r.size(), 1U);
  EXPECT_EQ(r[0].error, make_error_code(MasterError::kDpv1Timeout));
  f.reply(kDxDl);
  EXPECT_EQ(f.step()[4], 0x05) << "no more polls after the timeout: next cycle's DX";
}

TEST(MasterDpv1, NoAnswerIsDistinctFromTimeout) {
  MasterFixture f;
  f.bring_to_dx();
  ASSERT_TRUE(f.master.read(5, 0, 1, 4));
  ASSERT_TRUE(f.master.read(5, 0, 2, 4));
  after_dx(f);  // request, no reply
  f.step();     // retry (same FCB)
  f.clock.set(*f.master.next_deadline());
  f.poke();  // gives up
  const auto r = f.events<Dpv1Result>();
  ASSERT_EQ(r.size(), 2U);
  EXPECT_EQ(r[0].error, make_error_code(MasterError::kNoAnswer));
  EXPECT_EQ(r[1].error, make_error_code(MasterError::kAborted));
  EXPECT_EQ(f.events<SlaveLeftDataExchange>().size(), 1U);
}

TEST(MasterDpv1, RsOnSap51IsSapNotEnabled) {
  MasterFixture f;
  f.bring_to_dx();
  ASSERT_TRUE(f.master.read(5, 0, 1, 4));
  after_dx(f);
  f.reply({0x10, 0x02, 0x05, 0x03, 0x0A, 0x16});
  EXPECT_EQ(f.events<Dpv1Result>().at(0).error, make_error_code(MasterError::kSapNotEnabled));
  EXPECT_EQ(f.master.slave_status(5)->state, PollState::kDataExchange);
}

TEST(MasterDpv1, NoResourceRepeatsTheRequest) {
  MasterFixture f;
  f.bring_to_dx();
  ASSERT_TRUE(f.master.read(5, 0, 1, 16));
  const Bytes req = after_dx(f);
  f.reply({0x10, 0x02, 0x05,
           0x02,  // FC RR: no resources (slave still busy with an earlier request)
           fcs({0x02, 0x05, 0x02}), 0x16});
  EXPECT_TRUE(f.events<Dpv1Result>().empty());
  const Bytes again = after_dx(f);
  ASSERT_EQ(again.size(), req.size()) << "the request PDU again, not an empty poll";
  EXPECT_EQ(hex(Bytes(again.begin() + 7, again.end() - 2)), "33 33 5E 00 01 10");
  f.reply({0xE5});
  EXPECT_EQ(after_dx(f).size(), 11U) << "then empty polls";
}

TEST(MasterDpv1, MismatchedResponseIsInvalid) {
  MasterFixture f;
  f.bring_to_dx();
  ASSERT_TRUE(f.master.read(5, 0, 1, 16));
  after_dx(f);
  // Read.res for index 2 instead of 1.
  f.reply({0x68, 0x0A, 0x0A, 0x68, 0x82, 0x85, 0x08, 0x33, 0x33, 0x5E, 0x00, 0x02, 0x01, 0x77,
           fcs({0x82, 0x85, 0x08, 0x33, 0x33, 0x5E, 0x00, 0x02, 0x01, 0x77}), 0x16});
  EXPECT_EQ(f.events<Dpv1Result>().at(0).error, make_error_code(MasterError::kInvalidResponse));
}

TEST(MasterDpv1, RequestsAreRejectedUpFront) {
  MasterFixture f;
  EXPECT_EQ(f.master.read(5, 0, 1, 4).error(), make_error_code(MasterError::kNotInDataExchange));
  EXPECT_EQ(f.master.read(9, 0, 1, 4).error(), make_error_code(MasterError::kUnknownSlave));
  f.bring_to_dx();
  EXPECT_EQ(f.master.read(5, 0, 1, 0).error(), make_error_code(MasterError::kBadArgument));
  EXPECT_EQ(f.master.read(5, 0, 1, 241).error(), make_error_code(MasterError::kBadArgument));
  EXPECT_EQ(f.master.write(5, 0, 1, Bytes{}).error(), make_error_code(MasterError::kBadArgument));
  EXPECT_EQ(f.master.write(5, 0, 1, Bytes(241, 0)).error(),
            make_error_code(MasterError::kBadArgument));
  for (std::size_t i = 0; i < Dpv1Client::kQueueLimit; ++i) ASSERT_TRUE(f.master.read(5, 0, 1, 4));
  EXPECT_EQ(f.master.read(5, 0, 1, 4).error(), make_error_code(MasterError::kQueueFull));

  MasterConfig cfg = example_master();
  cfg.slaves[0].prm.dpv1.reset();  // DPV0 parameterisation
  MasterFixture g(cfg);
  // Bring up with the DPV0 Set_Prm (7 bytes); the rest of the start-up is the same.
  g.bring_to_dx();
  EXPECT_EQ(g.master.read(5, 0, 1, 4).error(), make_error_code(MasterError::kDpv1NotEnabled));
}

TEST(MasterDpv1, LeavingDataExchangeAbortsQueuedRequests) {
  MasterFixture f;
  f.bring_to_dx();
  ASSERT_TRUE(f.master.read(5, 0, 1, 4));
  f.step();
  f.reply({0x10, 0x02, 0x05, 0x03, 0x0A, 0x16});  // RS to the DX
  const auto r = f.events<Dpv1Result>();
  ASSERT_EQ(r.size(), 1U);
  EXPECT_EQ(r[0].error, make_error_code(MasterError::kAborted));
}

}  // namespace
}  // namespace rs4sim::dp::master::testing
