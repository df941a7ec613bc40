// Slave_Diag response, [IEC 61158-6-3 Slave_Diag]; vectors from
// [docs/references.md#dp-worked-example] and [pyprofibus issue #26 trace].
#include "dp/pdu/slave_diag.h"

#include "pdu_test_util.h"

namespace rs4sim::dp::pdu {
namespace {

using testing::Bytes;
using testing::error_of;

Result<void> enc(const SlaveDiag& d, fdl::DataUnit& out) { return encode_slave_diag(d, out); }

TEST(PduSlaveDiag, WaitPrmAfterPowerOn) {
  const Bytes du = {
      0x02,        // 0 Station_Status_1: Station_Not_Ready (b1)
      0x05,        // 1 Station_Status_2: Prm_Req (b0) + always 1 (b2)
      0x00,        // 2 Station_Status_3
      0xFF,        // 3 Master_Add: not parameterized
      0x12, 0x34,  // 4,5 Ident_Number
  };
  const auto r = decode_slave_diag(du);
  ASSERT_TRUE(r);
  const SlaveDiag& d = r.value();
  EXPECT_TRUE(d.status1.station_not_ready);
  EXPECT_FALSE(d.status1.cfg_fault);
  EXPECT_TRUE(d.status2.prm_req);
  EXPECT_TRUE(d.status2.always_one);
  EXPECT_FALSE(d.status2.wd_on);
  EXPECT_EQ(d.master_add, 0xFF);
  EXPECT_EQ(d.ident_number, 0x1234);
  EXPECT_TRUE(d.ext_diag.empty());
  SlaveDiag built;
  built.status1.station_not_ready = true;
  built.status2.prm_req = true;
  built.ident_number = 0x1234;
  EXPECT_EQ(testing::encoded(enc, built), du);
}

TEST(PduSlaveDiag, ReadyInDataExchange) {
  const Bytes du = {0x00,
                    0x0C,  // 1 WD_On (b3) + always 1 (b2)
                    0x00,
                    0x02,  // 3 Master_Add = master 2
                    0x12, 0x34};
  SlaveDiag d;
  d.status2.wd_on = true;
  d.master_add = 2;
  d.ident_number = 0x1234;
  EXPECT_EQ(testing::encoded(enc, d), du);
  EXPECT_EQ(decode_slave_diag(du).value(), d);
}

TEST(PduSlaveDiag, Et200sWithIdentifierBlock) {
  const Bytes du = {0x02, 0x05, 0x00, 0xFF, 0x80, 0x6A,
                    0x49,  // 6 identifier-related block, length 9 incl. header
                    0,    0,    0,    0,    0,    0,    0, 0};
  const auto r = decode_slave_diag(du);
  ASSERT_TRUE(r);
  EXPECT_EQ(r.value().ident_number, 0x806A);
  EXPECT_EQ(r.value().ext_diag.size(), 9U);
  EXPECT_EQ(testing::encoded(enc, r.value()), du);
}

TEST(PduSlaveDiag, EveryStationStatusBit) {
  const char* names1[] = {
      "Station_Non_Existent", "Station_Not_Ready",      "Cfg_Fault", "Ext_Diag",
      "Not_Supported",        "Invalid_Slave_Response", "Prm_Fault", "Master_Lock"};
  for (unsigned b = 0; b < 8; ++b) {
    SCOPED_TRACE(names1[b]);
    const auto byte = static_cast<std::uint8_t>(1U << b);
    const StationStatus1 s = StationStatus1::from_byte(byte);
    const bool bits[] = {
        s.station_non_existent, s.station_not_ready,      s.cfg_fault, s.ext_diag,
        s.not_supported,        s.invalid_slave_response, s.prm_fault, s.master_lock};
    for (unsigned i = 0; i < 8; ++i) EXPECT_EQ(bits[i], i == b);
    EXPECT_EQ(s.to_byte(), byte);
    const StationStatus2 t = StationStatus2::from_byte(byte);
    const bool bits2[] = {t.prm_req,     t.stat_diag, t.always_one, t.wd_on,
                          t.freeze_mode, t.sync_mode, t.reserved,   t.deactivated};
    for (unsigned i = 0; i < 8; ++i) EXPECT_EQ(bits2[i], i == b);
    EXPECT_EQ(t.to_byte(), byte);
  }
  EXPECT_TRUE(StationStatus3::from_byte(0x80).ext_diag_overflow);
  EXPECT_EQ(StationStatus3::from_byte(0x81).to_byte(), 0x81);
  EXPECT_EQ(StationStatus3::from_byte(0x7F).reserved, 0x7F);
}

TEST(PduSlaveDiag, LengthErrors) {
  const Bytes five = {0x02, 0x05, 0x00, 0xFF, 0x12};
  EXPECT_EQ(error_of(decode_slave_diag(five)), PduError::kTooShort);
  const Bytes big(245, 0);
  EXPECT_EQ(error_of(decode_slave_diag(big)), PduError::kTooLong);
  SlaveDiag d;
  d.ext_diag.assign(238, 0);
  fdl::DataUnit out;
  out.push_back(0);  // already one byte in the DU: 1 + 244 > 244
  EXPECT_EQ(error_of(encode_slave_diag(d, out)), PduError::kTooLong);
}

}  // namespace
}  // namespace rs4sim::dp::pdu
