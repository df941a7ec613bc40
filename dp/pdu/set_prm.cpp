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

namespace {

// Where each DPV1_Status field stands: its byte (0..2 for DPV1_Status_1..3) and its bit, or
// its mask for the fields kept in place. The one layout both directions read.
struct FlagAt {
  bool Dpv1Status::*member;
  std::size_t byte;
  unsigned bit;
};
struct FieldAt {
  std::uint8_t Dpv1Status::*member;
  std::size_t byte;
  std::uint8_t mask;
};

constexpr FlagAt kDpv1Flags[] = {
    {&Dpv1Status::dpv1_enable, 0, 7},
    {&Dpv1Status::fail_safe, 0, 6},
    {&Dpv1Status::publisher_enable, 0, 5},
    {&Dpv1Status::wd_base_1ms, 0, 2},
    {&Dpv1Status::enable_pull_plug_alarm, 1, 7},
    {&Dpv1Status::enable_process_alarm, 1, 6},
    {&Dpv1Status::enable_diagnostic_alarm, 1, 5},
    {&Dpv1Status::enable_manufacturer_specific_alarm, 1, 4},
    {&Dpv1Status::enable_status_alarm, 1, 3},
    {&Dpv1Status::enable_update_alarm, 1, 2},
    {&Dpv1Status::check_cfg_mode, 1, 0},
    {&Dpv1Status::prm_cmd, 2, 7},
    {&Dpv1Status::isom_req, 2, 4},
    {&Dpv1Status::prm_structure, 2, 3},
};
constexpr FieldAt kDpv1Fields[] = {
    {&Dpv1Status::status1_reserved, 0, 0x1B},
    {&Dpv1Status::status2_reserved, 1, 0x02},
    {&Dpv1Status::alarm_mode, 2, 0x07},
    {&Dpv1Status::status3_reserved, 2, 0x60},
};

}  // namespace

std::array<std::uint8_t, 3> Dpv1Status::to_bytes() const {
  std::array<std::uint8_t, 3> s{};
  for (const auto& f : kDpv1Flags) {
    s[f.byte] = static_cast<std::uint8_t>(s[f.byte] | flag(this->*f.member, f.bit));
  }
  for (const auto& f : kDpv1Fields) {
    s[f.byte] = static_cast<std::uint8_t>(s[f.byte] | (this->*f.member & f.mask));
  }
  return s;
}

Dpv1Status Dpv1Status::from_bytes(std::uint8_t s1, std::uint8_t s2, std::uint8_t s3) {
  const std::array<std::uint8_t, 3> s{s1, s2, s3};
  Dpv1Status d;
  for (const auto& f : kDpv1Flags) d.*f.member = bit(s[f.byte], f.bit);
  for (const auto& f : kDpv1Fields) d.*f.member = static_cast<std::uint8_t>(s[f.byte] & f.mask);
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
