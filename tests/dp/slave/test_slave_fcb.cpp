// FCB/FCV responder rule on the slave ([IEC 61158-4-3 FCB/FCV]) and the address filter
// ([IEC 61158-4-3 frame reception]): a repeat gets the stored reply and is not executed again.
#include "tests/dp/slave/slave_harness.h"

namespace rs4sim::dp::testing {
using namespace ::rs4sim::dp::slave;  // the slave under test
namespace {

TEST(SlaveFcb, RepeatedDataExchangeIsAnsweredFromTheStoreNotExecuted) {
  SlaveHarness h;
  h.to_data_exchange();  // 6D Set_Prm, 5D Chk_Cfg
  const Bytes dx{0x68, 0x04, 0x04, 0x68, 0x05, 0x02,
                 0x7D,  // FCV=1, FCB=1: new (last was FCB=0)
                 0xA5, 0x29, 0x16};
  const Bytes reply{0x68, 0x04, 0x04, 0x68, 0x02, 0x05, 0x08, 0x3C, 0x4B, 0x16};
  EXPECT_EQ(h.send(dx), reply);
  h.app.inputs = {0x77};         // a second execution would answer 77
  EXPECT_EQ(h.send(dx), reply);  // same FCB from the same master: repeat
  EXPECT_EQ(h.app.outputs.size(), 1U);
  EXPECT_EQ(h.slave.counters().repeats_answered, 1U);
  // Toggled FCB: executed again with the new inputs.
  const Bytes dx_new{0x68, 0x04, 0x04, 0x68, 0x05, 0x02, 0x5D, 0xA5, 0x09, 0x16};
  EXPECT_EQ(h.send(dx_new), (Bytes{0x68, 0x04, 0x04, 0x68, 0x02, 0x05, 0x08, 0x77, 0x86, 0x16}));
  EXPECT_EQ(h.app.outputs.size(), 2U);
}

TEST(SlaveFcb, RepeatedSetPrmIsNotExecutedTwice) {
  SlaveHarness h;
  const Bytes prm = h.dp(0x3D, SlaveHarness::example_prm());
  EXPECT_EQ(h.send(prm), kSc);
  const Bytes cfg = h.dp(0x3E, {0x10, 0x20});
  EXPECT_EQ(h.send(cfg), kSc);
  ASSERT_EQ(h.slave.state(), State::kDataExch);
  EXPECT_EQ(h.send(cfg), kSc);  // repeat of Chk_Cfg: stored SC
  EXPECT_EQ(h.app.transitions.size(), 2U);
}

TEST(SlaveFcb, FirstFrameFromAnotherMasterIsNotARepeat) {
  SlaveHarness h;
  // Master 2: Slave_Diag with 6D. Master 3: Slave_Diag with 6D too — a different SA.
  EXPECT_EQ(h.send(sd2({0x85, 0x82, 0x6D, 0x3C, 0x3E})).size(), 17U);
  const Bytes from3 = sd2({0x85, 0x83, 0x6D, 0x3C, 0x3E});
  const Bytes reply3 = sd2({0x83, 0x85, 0x08, 0x3E, 0x3C, 0x02, 0x05, 0x00, 0xFF, 0x12, 0x34});
  EXPECT_EQ(h.send(from3), reply3);
  EXPECT_EQ(h.slave.counters().repeats_answered, 0U);
}

TEST(SlaveFcb, FdlStatusHasNoFcbAndDoesNotDisturbTheStore) {
  SlaveHarness h;
  h.to_data_exchange();
  const Bytes dx = h.dx({0x11});
  const Bytes r1 = h.send(dx);
  EXPECT_EQ(h.send(Bytes{0x10, 0x05, 0x02, 0x49, 0x50, 0x16}),
            (Bytes{0x10, 0x02, 0x05, 0x00, 0x07, 0x16}));
  EXPECT_EQ(h.send(dx), r1);  // still recognised as repeat after FDL_Status
  EXPECT_EQ(h.app.outputs.size(), 1U);
}

TEST(SlaveAddressFilter, OtherStationsTokensAndResponsesAreIgnored) {
  SlaveHarness h;
  EXPECT_TRUE(h.send(sd2({0x86, 0x82, 0x6D, 0x3C, 0x3E})).empty());  // DA 6
  EXPECT_TRUE(h.send(Bytes{0xDC, 0x05, 0x02}).empty());              // token to 5
  EXPECT_TRUE(h.send(Bytes{0xE5}).empty());                          // SC
  EXPECT_TRUE(h.send(sd1(0x05, 0x02, 0x08)).empty());                // a response FC
  EXPECT_EQ(h.slave.counters().for_other_stations, 1U);
  EXPECT_EQ(h.slave.counters().ignored, 3U);
  EXPECT_EQ(h.slave.counters().telegrams_seen, 4U);
}

TEST(SlaveAddressFilter, BroadcastIsNeverAnswered) {
  SlaveHarness h;
  // SRD to 127 with a Slave_Diag: must stay silent ([IEC 61158-4-3 frame reception]).
  EXPECT_TRUE(h.send(sd2({0xFF, 0x82, 0x4D, 0x3C, 0x3E})).empty());
  // SDN broadcast Data_Exchange: silent and not executed.
  EXPECT_TRUE(h.send(sd2({0x7F, 0x02, 0x46, 0xA5})).empty());
  EXPECT_TRUE(h.app.outputs.empty());
}

TEST(SlaveAddressFilter, IdentAndLsapStatusAreNotOffered) {
  SlaveHarness h;
  EXPECT_EQ(h.send(sd1(0x05, 0x02, 0x4E)), (Bytes{0x10, 0x02, 0x05, 0x03, 0x0A, 0x16}));
  EXPECT_EQ(h.send(sd1(0x05, 0x02, 0x4F)), (Bytes{0x10, 0x02, 0x05, 0x03, 0x0A, 0x16}));
  EXPECT_TRUE(h.send(sd1(0x05, 0x02, 0x40)).empty());  // time event: no reply
}

TEST(SlaveAddressFilter, SdaIsOnlyAcknowledged) {
  SlaveHarness h;
  // SDA high (FC 0x55 = FCV + func 5) to Slave_Diag: SC instead of data.
  EXPECT_EQ(h.send(sd2({0x85, 0x82, 0x55, 0x3C, 0x3E})), kSc);
}

TEST(SlaveAddressFilter, MalformedFramesAreCountedWhenTheLinkReportsThem) {
  SlaveHarness h;
  Station& station = h.slave;  // links only see dp::Station
  station.on_malformed_frame(fdl::DecodeError::kBadFcs);
  station.on_malformed_frame(fdl::DecodeError::kLengthMismatch);
  EXPECT_EQ(h.slave.counters().malformed_dropped, 2U);
  EXPECT_EQ(station.min_tsdr_bits(), 11);
  h.send(h.dp(0x3D, {0x88, 0x0A, 0x01, 0x1E, 0x12, 0x34, 0x00, 0x80, 0x20, 0x00}));  // min TSDR 30
  EXPECT_EQ(station.min_tsdr_bits(), 30);
}

}  // namespace
}  // namespace rs4sim::dp::testing
