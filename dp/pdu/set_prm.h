#pragma once
// Set_Prm request (DSAP 61), [IEC 61158-6-3 Set_Prm], with the DPV1 status bytes
// [IEC 61158-6-3 DPV1_Status].
//
// DU: [0] Station_Status [1] WD_Fact_1 [2] WD_Fact_2 [3] min TSDR [4..5] Ident_Number (BE)
//     [6] Group_Ident [7..9] DPV1_Status_1..3 (DPV1 layout only) [..] User_Prm_Data.
// Reserved bits are kept (not rejected) so that decode(encode(x)) is byte-exact; the
// slave decides what a reserved bit means for Prm_Fault.

#include "dp/fdl/telegram.h"
#include "dp/pdu/errors.h"

#include <boost/container/static_vector.hpp>

#include <array>
#include <chrono>
#include <cstdint>
#include <optional>
#include <span>

namespace rs4sim::dp::pdu {

inline constexpr std::size_t kSetPrmFixedLength = 7;  // standard bytes
inline constexpr std::size_t kSetPrmDpv1Length = 10;  // PRM_LEN_DPV1 ([IEC 61158-6-3 DPV1_Status])
inline constexpr std::size_t kSetPrmMaxLength = 244;  // [IEC 61158-6-3 Set_Prm] length limits

// Set_Prm byte 0 ([IEC 61158-6-3 Set_Prm]).
struct PrmStationStatus {
  bool lock_req = false;      // bit 7
  bool unlock_req = false;    // bit 6
  bool sync_req = false;      // bit 5
  bool freeze_req = false;    // bit 4
  bool wd_on = false;         // bit 3
  std::uint8_t reserved = 0;  // bits 2..0 (0 on the wire)

  [[nodiscard]] std::uint8_t to_byte() const;
  static PrmStationStatus from_byte(std::uint8_t b);
  friend bool operator==(const PrmStationStatus&, const PrmStationStatus&) = default;
};

// Set_Prm bytes 7..9 = DPV1_Status_1..3 ([IEC 61158-6-3 DPV1_Status]).
struct Dpv1Status {
  // DPV1_Status_1
  bool dpv1_enable = false;           // bit 7
  bool fail_safe = false;             // bit 6
  bool publisher_enable = false;      // bit 5
  bool wd_base_1ms = false;           // bit 2
  std::uint8_t status1_reserved = 0;  // bits 4,3,1,0 in place (mask 0x1B)
  // DPV1_Status_2
  bool enable_pull_plug_alarm = false;              // bit 7
  bool enable_process_alarm = false;                // bit 6
  bool enable_diagnostic_alarm = false;             // bit 5
  bool enable_manufacturer_specific_alarm = false;  // bit 4
  bool enable_status_alarm = false;                 // bit 3
  bool enable_update_alarm = false;                 // bit 2
  bool check_cfg_mode = false;                      // bit 0
  std::uint8_t status2_reserved = 0;                // bit 1 in place (mask 0x02)
  // DPV1_Status_3
  bool prm_cmd = false;               // bit 7
  bool isom_req = false;              // bit 4
  bool prm_structure = false;         // bit 3
  std::uint8_t alarm_mode = 0;        // bits 2..0
  std::uint8_t status3_reserved = 0;  // bits 6,5 in place (mask 0x60)

  [[nodiscard]] std::array<std::uint8_t, 3> to_bytes() const;
  static Dpv1Status from_bytes(std::uint8_t s1, std::uint8_t s2, std::uint8_t s3);
  // Alarm_Mode → max outstanding alarms: 0 = one per type (returns 1), 1..7 = 2,4,8,12,16,24,32.
  [[nodiscard]] unsigned max_outstanding_alarms() const;
  [[nodiscard]] bool any_alarm_enabled() const;
  friend bool operator==(const Dpv1Status&, const Dpv1Status&) = default;
};

using UserPrmData =
    boost::container::static_vector<std::uint8_t, kSetPrmMaxLength - kSetPrmFixedLength>;

struct SetPrm {
  PrmStationStatus station_status;
  std::uint8_t wd_fact_1 = 1;
  std::uint8_t wd_fact_2 = 1;
  std::uint8_t min_tsdr = 0;  // Tbit; 0 = leave unchanged
  std::uint16_t ident_number = 0;
  std::uint8_t group_ident = 0;
  std::optional<Dpv1Status> dpv1;  // present ⇔ DPV1 layout and DU ≥ 10 bytes
  UserPrmData user_data;

  // T_WD = WD base · F1 · F2 (base 10 ms, 1 ms with WD_Base_1ms); nullopt if WD_On=0
  // ([IEC 61158-6-3 Set_Prm]).
  [[nodiscard]] std::optional<std::chrono::milliseconds> watchdog_time() const;
  friend bool operator==(const SetPrm&, const SetPrm&) = default;
};

// How bytes 7..9 are read: a DPV1 slave (GSD DPV1_Slave=1) reads them as DPV1_Status when
// the DU has ≥ 10 bytes; a DPV0 slave reads everything after byte 6 as User_Prm_Data.
enum class PrmLayout : std::uint8_t { kDpv0, kDpv1 };

// Errors: kTooShort (< 7), kTooLong (> 244).
Result<SetPrm> decode_set_prm(std::span<const std::uint8_t> du, PrmLayout layout);
// Errors: kTooLong when the DU would exceed 244 bytes.
Result<void> encode_set_prm(const SetPrm& prm, fdl::DataUnit& out);

}  // namespace rs4sim::dp::pdu
