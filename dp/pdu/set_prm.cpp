// Set_Prm, [IEC 61158-6-3 Set_Prm] and DPV1_Status [IEC 61158-6-3 DPV1_Status].
#include "dp/pdu/set_prm.h"

#include "dp/pdu/wire.h"

namespace rs4sim::dp::pdu {

using wire::bit;
using wire::flag;

std::uint8_t PrmStationStatus::to_byte() const {
  return static_cast<std::uint8_t>(flag(lock_req, 7) | flag(unlock_req, 6) | flag(sync_req, 5) |
                                   flag(freeze_req, 4) | flag(wd_on, 3) | (reserved & 0x07U));
}

PrmStationStatus PrmStationStatus::from_byte(std::uint8_t b) {
  return {bit(b, 7), bit(b, 6), bit(b, 5),
          bit(b, 4), bit(b, 3), static_cast<std::uint8_t>(b & 0x07U)};
}

std::array<std::uint8_t, 3> Dpv1Status::to_bytes() const {
  const auto s1 = static_cast<std::uint8_t>(flag(dpv1_enable, 7) | flag(fail_safe, 6) |
                                            flag(publisher_enable, 5) | flag(wd_base_1ms, 2) |
                                            (status1_reserved & 0x1BU));
  const auto s2 = static_cast<std::uint8_t>(
      flag(enable_pull_plug_alarm, 7) | flag(enable_process_alarm, 6) |
      flag(enable_diagnostic_alarm, 5) | flag(enable_manufacturer_specific_alarm, 4) |
      flag(enable_status_alarm, 3) | flag(enable_update_alarm, 2) | flag(check_cfg_mode, 0) |
      (status2_reserved & 0x02U));
  const auto s3 =
      static_cast<std::uint8_t>(flag(prm_cmd, 7) | flag(isom_req, 4) | flag(prm_structure, 3) |
                                (alarm_mode & 0x07U) | (status3_reserved & 0x60U));
  return {s1, s2, s3};
}

Dpv1Status Dpv1Status::from_bytes(std::uint8_t s1, std::uint8_t s2, std::uint8_t s3) {
  Dpv1Status d;
  d.dpv1_enable = bit(s1, 7);
  d.fail_safe = bit(s1, 6);
  d.publisher_enable = bit(s1, 5);
  d.wd_base_1ms = bit(s1, 2);
  d.status1_reserved = static_cast<std::uint8_t>(s1 & 0x1BU);
  d.enable_pull_plug_alarm = bit(s2, 7);
  d.enable_process_alarm = bit(s2, 6);
  d.enable_diagnostic_alarm = bit(s2, 5);
  d.enable_manufacturer_specific_alarm = bit(s2, 4);
  d.enable_status_alarm = bit(s2, 3);
  d.enable_update_alarm = bit(s2, 2);
  d.check_cfg_mode = bit(s2, 0);
  d.status2_reserved = static_cast<std::uint8_t>(s2 & 0x02U);
  d.prm_cmd = bit(s3, 7);
  d.isom_req = bit(s3, 4);
  d.prm_structure = bit(s3, 3);
  d.alarm_mode = static_cast<std::uint8_t>(s3 & 0x07U);
  d.status3_reserved = static_cast<std::uint8_t>(s3 & 0x60U);
  return d;
}

unsigned Dpv1Status::max_outstanding_alarms() const {
  // [IEC 61158-6-3 DPV1_Status] Alarm_Mode
  static constexpr unsigned kTotals[8] = {1, 2, 4, 8, 12, 16, 24, 32};
  return kTotals[alarm_mode & 0x07U];
}

bool Dpv1Status::any_alarm_enabled() const {
  return enable_pull_plug_alarm || enable_process_alarm || enable_diagnostic_alarm ||
         enable_manufacturer_specific_alarm || enable_status_alarm || enable_update_alarm;
}

std::optional<std::chrono::milliseconds> SetPrm::watchdog_time() const {
  if (!station_status.wd_on) return std::nullopt;
  const long base = (dpv1 && dpv1->wd_base_1ms) ? 1 : 10;
  return std::chrono::milliseconds(base * wd_fact_1 * wd_fact_2);
}

Result<SetPrm> decode_set_prm(std::span<const std::uint8_t> du, PrmLayout layout) {
  if (du.size() < kSetPrmFixedLength) return PduError::kTooShort;
  if (du.size() > kSetPrmMaxLength) return PduError::kTooLong;
  SetPrm p;
  p.station_status = PrmStationStatus::from_byte(du[0]);
  p.wd_fact_1 = du[1];
  p.wd_fact_2 = du[2];
  p.min_tsdr = du[3];
  p.ident_number = codec::be16(du[4], du[5]);
  p.group_ident = du[6];
  std::size_t user = kSetPrmFixedLength;
  if (layout == PrmLayout::kDpv1 && du.size() >= kSetPrmDpv1Length) {
    p.dpv1 = Dpv1Status::from_bytes(du[7], du[8], du[9]);
    user = kSetPrmDpv1Length;
  }
  p.user_data.assign(du.begin() + static_cast<std::ptrdiff_t>(user), du.end());
  return p;
}

Result<void> encode_set_prm(const SetPrm& prm, fdl::DataUnit& out) {
  const std::size_t size = kSetPrmFixedLength + (prm.dpv1 ? 3U : 0U) + prm.user_data.size();
  if (out.size() + size > wire::kMaxDpDu) return PduError::kTooLong;
  (void)wire::append(out, {prm.station_status.to_byte(), prm.wd_fact_1, prm.wd_fact_2, prm.min_tsdr,
                           codec::high_byte(prm.ident_number), codec::low_byte(prm.ident_number),
                           prm.group_ident});
  if (prm.dpv1) (void)wire::append(out, prm.dpv1->to_bytes());
  return wire::append(out, prm.user_data);
}

}  // namespace rs4sim::dp::pdu
