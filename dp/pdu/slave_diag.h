#pragma once
// Slave_Diag response (DSAP 60 → master SSAP 62), [IEC 61158-6-3 Slave_Diag].
// DU: [0] Station_Status_1 [1] Station_Status_2 [2] Station_Status_3 [3] Diag.Master_Add
//     [4..5] Ident_Number (BE) [6..] extended diagnosis blocks (see ext_diag.h).

#include "dp/fdl/telegram.h"
#include "dp/pdu/errors.h"

#include <boost/container/static_vector.hpp>

#include <cstdint>
#include <span>

namespace rs4sim::dp::pdu {

inline constexpr std::size_t kDiagStandardLength = 6;
inline constexpr std::size_t kDiagMaxLength = 244;
inline constexpr std::size_t kExtDiagMaxLength = kDiagMaxLength - kDiagStandardLength;  // 238

// Station_Status_1 ([IEC 61158-6-3 Slave_Diag]). (M) = set by the master only; a slave sends 0.
struct StationStatus1 {
  bool station_non_existent = false;    // bit 0 (M)
  bool station_not_ready = false;       // bit 1
  bool cfg_fault = false;               // bit 2
  bool ext_diag = false;                // bit 3
  bool not_supported = false;           // bit 4
  bool invalid_slave_response = false;  // bit 5 (M)
  bool prm_fault = false;               // bit 6
  bool master_lock = false;             // bit 7 (M)
  [[nodiscard]] std::uint8_t to_byte() const;
  static StationStatus1 from_byte(std::uint8_t b);
  friend bool operator==(const StationStatus1&, const StationStatus1&) = default;
};

// Station_Status_2 ([IEC 61158-6-3 Slave_Diag]).
struct StationStatus2 {
  bool prm_req = false;      // bit 0
  bool stat_diag = false;    // bit 1
  bool always_one = true;    // bit 2 (a slave always sends 1)
  bool wd_on = false;        // bit 3
  bool freeze_mode = false;  // bit 4
  bool sync_mode = false;    // bit 5
  bool reserved = false;     // bit 6
  bool deactivated = false;  // bit 7 (M)
  [[nodiscard]] std::uint8_t to_byte() const;
  static StationStatus2 from_byte(std::uint8_t b);
  friend bool operator==(const StationStatus2&, const StationStatus2&) = default;
};

// Station_Status_3 ([IEC 61158-6-3 Slave_Diag]).
struct StationStatus3 {
  bool ext_diag_overflow = false;  // bit 7
  std::uint8_t reserved = 0;       // bits 6..0
  [[nodiscard]] std::uint8_t to_byte() const;
  static StationStatus3 from_byte(std::uint8_t b);
  friend bool operator==(const StationStatus3&, const StationStatus3&) = default;
};

using ExtDiagData = boost::container::static_vector<std::uint8_t, kExtDiagMaxLength>;

struct SlaveDiag {
  StationStatus1 status1;
  StationStatus2 status2;
  StationStatus3 status3;
  std::uint8_t master_add = 0xFF;  // FF = not parameterized
  std::uint16_t ident_number = 0;
  ExtDiagData ext_diag;  // concatenated blocks; parse with ExtDiagReader (ext_diag.h)
  friend bool operator==(const SlaveDiag&, const SlaveDiag&) = default;
};

// Errors: kTooShort (< 6), kTooLong (> 244). Block syntax is checked by ExtDiagReader.
Result<SlaveDiag> decode_slave_diag(std::span<const std::uint8_t> du);
// Errors: kTooLong (ext_diag cannot exceed 238, so only if the DU already holds bytes).
Result<void> encode_slave_diag(const SlaveDiag& diag, fdl::DataUnit& out);

}  // namespace rs4sim::dp::pdu
