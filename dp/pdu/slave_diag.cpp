// Slave_Diag response, [IEC 61158-6-3 Slave_Diag].
#include "dp/pdu/slave_diag.h"

#include "dp/pdu/wire.h"

namespace rs4sim::dp::pdu {

using wire::bit;
using wire::flag;

std::uint8_t StationStatus1::to_byte() const {
  return static_cast<std::uint8_t>(flag(station_non_existent, 0) | flag(station_not_ready, 1) |
                                   flag(cfg_fault, 2) | flag(ext_diag, 3) | flag(not_supported, 4) |
                                   flag(invalid_slave_response, 5) | flag(prm_fault, 6) |
                                   flag(master_lock, 7));
}

StationStatus1 StationStatus1::from_byte(std::uint8_t b) {
  return {bit(b, 0), bit(b, 1), bit(b, 2), bit(b, 3), bit(b, 4), bit(b, 5), bit(b, 6), bit(b, 7)};
}

std::uint8_t StationStatus2::to_byte() const {
  return static_cast<std::uint8_t>(flag(prm_req, 0) | flag(stat_diag, 1) | flag(always_one, 2) |
                                   flag(wd_on, 3) | flag(freeze_mode, 4) | flag(sync_mode, 5) |
                                   flag(reserved, 6) | flag(deactivated, 7));
}

StationStatus2 StationStatus2::from_byte(std::uint8_t b) {
  return {bit(b, 0), bit(b, 1), bit(b, 2), bit(b, 3), bit(b, 4), bit(b, 5), bit(b, 6), bit(b, 7)};
}

std::uint8_t StationStatus3::to_byte() const {
  return static_cast<std::uint8_t>(flag(ext_diag_overflow, 7) | (reserved & 0x7FU));
}

StationStatus3 StationStatus3::from_byte(std::uint8_t b) {
  return {bit(b, 7), static_cast<std::uint8_t>(b & 0x7FU)};
}

Result<SlaveDiag> decode_slave_diag(std::span<const std::uint8_t> du) {
  if (du.size() < kDiagStandardLength) return PduError::kTooShort;
  if (du.size() > kDiagMaxLength) return PduError::kTooLong;
  SlaveDiag d;
  d.status1 = StationStatus1::from_byte(du[0]);
  d.status2 = StationStatus2::from_byte(du[1]);
  d.status3 = StationStatus3::from_byte(du[2]);
  d.master_add = du[3];
  d.ident_number = codec::be16(du[4], du[5]);
  d.ext_diag.assign(du.begin() + kDiagStandardLength, du.end());
  return d;
}

Result<void> encode_slave_diag(const SlaveDiag& diag, fdl::DataUnit& out) {
  if (out.size() + kDiagStandardLength + diag.ext_diag.size() > wire::kMaxDpDu) {
    return PduError::kTooLong;
  }
  (void)wire::append(
      out, {diag.status1.to_byte(), diag.status2.to_byte(), diag.status3.to_byte(), diag.master_add,
            codec::high_byte(diag.ident_number), codec::low_byte(diag.ident_number)});
  return wire::append(out, diag.ext_diag);
}

}  // namespace rs4sim::dp::pdu
