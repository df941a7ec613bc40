// Set_Prm, [IEC 61158-6-3 Set_Prm] and DPV1_Status [IEC 61158-6-3 DPV1_Status]; vectors from
// [docs/references.md#dp-worked-example] and [pyprofibus issue #26 trace].
#include "dp/pdu/set_prm.h"

#include "pdu_test_util.h"

namespace rs4sim::dp::pdu {
namespace {

using testing::Bytes;
using testing::error_of;

Result<void> enc(const SetPrm& p, fdl::DataUnit& out) { return encode_set_prm(p, out); }

TEST(PduSetPrm, WorkedExampleDpv1) {
  const Bytes du = {
      0x88,        // 0 Station_Status: Lock_Req (b7) + WD_On (b3)
      0x0A,        // 1 WD_Fact_1 = 10
      0x01,        // 2 WD_Fact_2 = 1
      0x0B,        // 3 min TSDR = 11 Tbit
      0x12, 0x34,  // 4,5 Ident_Number 0x1234
      0x00,        // 6 Group_Ident
      0x80,        // 7 DPV1_Status_1: DPV1_Enable
      0x20,        // 8 DPV1_Status_2: Enable_Diagnostic_Alarm
      0x00,        // 9 DPV1_Status_3: Alarm_Mode 0
  };
  const auto r = decode_set_prm(du, PrmLayout::kDpv1);
  ASSERT_TRUE(r);
  const SetPrm& p = r.value();
  EXPECT_TRUE(p.station_status.lock_req);
  EXPECT_FALSE(p.station_status.unlock_req);
  EXPECT_FALSE(p.station_status.sync_req);
  EXPECT_FALSE(p.station_status.freeze_req);
  EXPECT_TRUE(p.station_status.wd_on);
  EXPECT_EQ(p.wd_fact_1, 10);
  EXPECT_EQ(p.wd_fact_2, 1);
  EXPECT_EQ(p.min_tsdr, 11);
  EXPECT_EQ(p.ident_number, 0x1234);
  EXPECT_EQ(p.group_ident, 0);
  ASSERT_TRUE(p.dpv1);
  EXPECT_TRUE(p.dpv1->dpv1_enable);
  EXPECT_TRUE(p.dpv1->enable_diagnostic_alarm);
  EXPECT_FALSE(p.dpv1->enable_process_alarm);
  EXPECT_EQ(p.dpv1->alarm_mode, 0);
  EXPECT_EQ(p.dpv1->max_outstanding_alarms(), 1U);
  EXPECT_TRUE(p.dpv1->any_alarm_enabled());
  EXPECT_TRUE(p.user_data.empty());
  EXPECT_EQ(p.watchdog_time(), std::chrono::milliseconds(100));  // 10 ms · 10 · 1
  EXPECT_EQ(testing::encoded(enc, p), du);
}

TEST(PduSetPrm, Et200sTraceDpv0WithUserData) {
  const Bytes du = {
      0xB8,        // 0 Lock_Req + Sync_Req + Freeze_Req + WD_On
      0x1E, 0x01,  // 1,2 WD factors 30 · 1
      0x00,        // 3 min TSDR 0 = keep
      0x80, 0x6A,  // 4,5 Ident 0x806A
      0x01,        // 6 Group_Ident: group 1
      0xAA, 0x55,  // 7.. User_Prm_Data (DPV0 layout: no DPV1 bytes)
  };
  const auto r = decode_set_prm(du, PrmLayout::kDpv0);
  ASSERT_TRUE(r);
  EXPECT_TRUE(r.value().station_status.sync_req);
  EXPECT_TRUE(r.value().station_status.freeze_req);
  EXPECT_FALSE(r.value().dpv1);
  EXPECT_EQ(r.value().user_data.size(), 2U);
  EXPECT_EQ(r.value().ident_number, 0x806A);
  EXPECT_EQ(r.value().watchdog_time(), std::chrono::milliseconds(300));
  EXPECT_EQ(testing::encoded(enc, r.value()), du);
}

TEST(PduSetPrm, Dpv1LayoutShorterThanTenBytesIsDpv0Mode) {
  // [IEC 61158-6-3 DPV1_Status]: DPV1 mode needs prm length ≥ 10; bytes 7..8 are then user data.
  const Bytes du = {0x80, 0x01, 0x01, 0x00, 0x12, 0x34, 0x00, 0x80, 0x20};
  const auto r = decode_set_prm(du, PrmLayout::kDpv1);
  ASSERT_TRUE(r);
  EXPECT_FALSE(r.value().dpv1);
  EXPECT_EQ(r.value().user_data.size(), 2U);
  EXPECT_FALSE(r.value().watchdog_time());  // WD_On = 0
}

TEST(PduSetPrm, EveryDpv1BitHasItsPlace) {
  // DPV1_Status_1 = 0xE4: Enable, Fail_Safe, Publisher, WD_Base_1ms.
  // DPV1_Status_2 = 0xFD: all six alarm enables + Check_Cfg_Mode.
  // DPV1_Status_3 = 0x9F: Prm_Cmd, IsoM_Req, Prm_Structure, Alarm_Mode 7.
  const Dpv1Status d = Dpv1Status::from_bytes(0xE4, 0xFD, 0x9F);
  EXPECT_TRUE(d.dpv1_enable && d.fail_safe && d.publisher_enable && d.wd_base_1ms);
  EXPECT_EQ(d.status1_reserved, 0);
  EXPECT_TRUE(d.enable_pull_plug_alarm && d.enable_process_alarm && d.enable_diagnostic_alarm &&
              d.enable_manufacturer_specific_alarm && d.enable_status_alarm &&
              d.enable_update_alarm && d.check_cfg_mode);
  EXPECT_TRUE(d.prm_cmd && d.isom_req && d.prm_structure);
  EXPECT_EQ(d.alarm_mode, 7);
  EXPECT_EQ(d.max_outstanding_alarms(), 32U);
  EXPECT_EQ(d.to_bytes(), (std::array<std::uint8_t, 3>{0xE4, 0xFD, 0x9F}));
  // Reserved bits survive a round trip (SPC3 reuses DPV1_Status_1 bits 1,0).
  const Dpv1Status r = Dpv1Status::from_bytes(0x1B, 0x02, 0x60);
  EXPECT_FALSE(r.dpv1_enable);
  EXPECT_EQ(r.to_bytes(), (std::array<std::uint8_t, 3>{0x1B, 0x02, 0x60}));
  EXPECT_EQ(Dpv1Status::from_bytes(0, 0, 4).max_outstanding_alarms(), 12U);
}

TEST(PduSetPrm, WatchdogBase1ms) {
  SetPrm p;
  p.station_status.wd_on = true;
  p.wd_fact_1 = 255;
  p.wd_fact_2 = 255;
  EXPECT_EQ(p.watchdog_time(), std::chrono::milliseconds(650250));  // 650.25 s maximum
  p.dpv1 = Dpv1Status{};
  p.dpv1->wd_base_1ms = true;
  EXPECT_EQ(p.watchdog_time(), std::chrono::milliseconds(65025));
}

TEST(PduSetPrm, StationStatusBits) {
  EXPECT_EQ(PrmStationStatus::from_byte(0x40).unlock_req, true);
  EXPECT_EQ(PrmStationStatus::from_byte(0x07).reserved, 7);
  EXPECT_EQ(PrmStationStatus::from_byte(0xFF).to_byte(), 0xFF);
  EXPECT_EQ((PrmStationStatus{true, false, false, false, true, 0}).to_byte(), 0x88);
}

TEST(PduSetPrm, LengthErrors) {
  const Bytes six = {0x88, 1, 1, 0, 0x12, 0x34};
  EXPECT_EQ(error_of(decode_set_prm(six, PrmLayout::kDpv1)), PduError::kTooShort);
  EXPECT_EQ(error_of(decode_set_prm({}, PrmLayout::kDpv0)), PduError::kTooShort);
  const Bytes big(245, 0);
  EXPECT_EQ(error_of(decode_set_prm(big, PrmLayout::kDpv0)), PduError::kTooLong);
  const Bytes max(244, 0);
  EXPECT_TRUE(decode_set_prm(max, PrmLayout::kDpv1));
  SetPrm p;
  p.dpv1 = Dpv1Status{};
  p.user_data.assign(235, 0);  // 7 + 3 + 235 = 245
  fdl::DataUnit out;
  EXPECT_EQ(error_of(encode_set_prm(p, out)), PduError::kTooLong);
  EXPECT_TRUE(out.empty());
}

}  // namespace
}  // namespace rs4sim::dp::pdu
