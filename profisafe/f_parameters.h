#pragma once
// The PROFIsafe F-parameter block ([IEC 61784-3-3 F-Parameters, CRC1]).
//
//   offset 0  F_Prm_Flag1   b0 F_Check_SeqNr, b1 F_Check_iPar, b2-3 F_SIL, b4-5 F_CRC_Length
//   offset 1  F_Prm_Flag2   b3-5 F_Block_ID, b6-7 F_Par_Version
//   offset 2  F_Source_Add  big-endian
//   offset 4  F_Dest_Add    big-endian
//   offset 6  F_WD_Time     big-endian, ms
//   offset 8  F_Par_CRC     big-endian, CRC1 (crc.h)
//
// Syntax (parse_f_parameters) is apart from meaning (validate): parsing only rejects a
// block that is not 10 bytes or has reserved bits set; validate() compares the fields
// with a DeviceProfile and names the first field the device refuses (FParameterFault);
// how a device numbers these faults in its diagnosis is the device's business.

#include "profisafe/errors.h"

#include <boost/outcome/std_result.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace rs4sim::profisafe {

template <class T>
using Result = boost::outcome_v2::std_result<T>;

inline constexpr std::size_t kFParametersSize = 10;

// F_SIL codes (F_Prm_Flag1 b2-3).
enum class Sil : std::uint8_t { kSil1 = 0, kSil2 = 1, kSil3 = 2, kNoSil = 3 };
// F_CRC_Length codes (F_Prm_Flag1 b4-5): 1 = 2-byte CRC2 (V1); V2: 0 = 3-byte, 2 = 4-byte.
enum class CrcLength : std::uint8_t { k3Byte = 0, k2Byte = 1, k4Byte = 2, kReserved = 3 };

struct FParameters {
  bool check_seqnr = false;                  // F_Check_SeqNr: consecutive number inside CRC2
  bool check_ipar = false;                   // F_Check_iPar
  Sil sil = Sil::kSil2;                      // F_SIL
  CrcLength crc_length = CrcLength::k2Byte;  // F_CRC_Length
  std::uint8_t block_id = 0;                 // F_Block_ID, 0..7
  std::uint8_t par_version = 0;              // F_Par_Version, 0 = V1, 1 = V2 (2 bits on the wire)
  std::uint16_t source_add = 1;              // F_Source_Add
  std::uint16_t dest_add = 504;              // F_Dest_Add
  std::uint16_t wd_time_ms = 10;             // F_WD_Time
  std::uint16_t par_crc = 0;                 // F_Par_CRC (CRC1) as carried in the block
  std::optional<std::uint32_t> ipar_crc;     // F_iPar_CRC (V2 only; not in the 10 bytes)

  friend bool operator==(const FParameters&, const FParameters&) = default;
};

// The 8 bytes CRC1 runs over (F_Prm_Flag1 .. F_WD_Time). block_id is masked to 3 bits,
// par_version to 2 bits (out-of-range values cannot be expressed on the wire).
[[nodiscard]] std::array<std::uint8_t, 8> encode_f_parameters_without_crc(
    const FParameters& p) noexcept;

// CRC1 of these parameters (over encode_f_parameters_without_crc, plus ipar_crc if set).
[[nodiscard]] std::uint16_t crc1(const FParameters& p) noexcept;

// The 10-byte block with F_Par_CRC computed in (p.par_crc is ignored).
[[nodiscard]] std::array<std::uint8_t, kFParametersSize> encode_f_parameters(
    const FParameters& p) noexcept;

// The 10-byte block carrying p.par_crc as given (for fault injection: wrong CRC1).
[[nodiscard]] std::array<std::uint8_t, kFParametersSize> encode_f_parameters_raw(
    const FParameters& p) noexcept;

// Parse the 10-byte block. Errors: ProfisafeError::kFParamsWrongSize,
// ProfisafeError::kFParamsReservedBits. The F_iPar_CRC is not part of the block; pass it if the
// configuration has one.
[[nodiscard]] Result<FParameters> parse_f_parameters(
    std::span<const std::uint8_t> block, std::optional<std::uint32_t> ipar_crc = std::nullopt);

// ---------------------------------------------------------------------------------
// Device-side validation: the F-parameter checks of IEC 61784-3-3 (PROFIsafe), in the
// order validate() makes them.

enum class FParameterFault : std::uint8_t {
  kNone = 0,
  kDestAddInvalid,     // the device itself has no valid F_Dest_Add (0 or 65535)
  kDestAddMismatch,    // F_Dest_Add is not the device's
  kSourceAddInvalid,   // F_Source_Add 0, 65535 or outside the device's range
  kWdTimeInvalid,      // F_WD_Time outside the device's range
  kSilMismatch,        // F_SIL is not the device's
  kCrcLengthMismatch,  // F_CRC_Length is not the device's
  kVersionMismatch,    // F_Block_ID, F_Par_Version or F_Check_iPar; or no block layout
  kCrc1Mismatch,       // F_Par_CRC is not CRC1 over the block
};
[[nodiscard]] const char* to_string(FParameterFault f) noexcept;

// The connections the drivers serve: V1 = F_Par_Version 0 with the 2-byte CRC2, V2 =
// F_Par_Version 1 with the 3- or 4-byte CRC2 ([IEC 61784-3-3 F-Parameters]).
[[nodiscard]] bool is_supported_connection(std::uint8_t par_version, CrcLength crc_length) noexcept;

// The standard F-device diagnosis of a fault ([IEC 61784-3-3 F-Parameters], the values a GSD's
// X_Value(64..71) texts name): 64 F_Dest_Add mismatch, 65 F_Dest_Add invalid, 66 F_Source_Add,
// 67 F_WD_Time, 68 SIL, 69 CRC length, 70 F-parameter version, 71 CRC1; 0 for kNone. A device
// may number them its own way (the RS4: rs4/safety/diagnosis.h).
[[nodiscard]] std::uint8_t standard_diagnosis(FParameterFault f) noexcept;
// Its meaning in the standard's words, for a diagnosis 64..71 ("" for any other value).
[[nodiscard]] const char* standard_diagnosis_text(std::uint8_t diagnosis) noexcept;

// What a device accepts: fixed values and ranges plus its own F_Dest_Add.
struct DeviceProfile {
  bool check_ipar = false;
  Sil sil = Sil::kSil2;
  CrcLength crc_length = CrcLength::k2Byte;
  std::uint8_t block_id = 0;
  std::uint8_t par_version = 0;
  std::uint16_t min_source_add = 1;
  std::uint16_t max_source_add = 65534;
  std::uint16_t min_wd_time_ms = 10;
  std::uint16_t max_wd_time_ms = 1000;
  // The device's own F_Dest_Add; 0 or 65535 = the device has no valid one
  // (kDestAddInvalid).
  std::uint16_t dest_add = 504;
};

// A device that takes exactly these fixed values (F_Check_iPar, SIL, CRC length, F_Block_ID,
// F_Par_Version) and whose own F_Dest_Add is p.dest_add; the ranges stay the defaults above.
[[nodiscard]] DeviceProfile profile_for(const FParameters& p) noexcept;

struct Validation {
  FParameterFault fault = FParameterFault::kNone;
  std::uint16_t received_crc1 = 0;  // F_Par_CRC as received
  std::uint16_t computed_crc1 = 0;  // CRC1 the device computed (for logging a CRC1 fault)
  [[nodiscard]] bool ok() const noexcept { return fault == FParameterFault::kNone; }
};

// Check the parameters against the profile. The first failing check in the enum's order
// is reported. F_Check_iPar != profile is reported as kVersionMismatch.
[[nodiscard]] Validation validate(const FParameters& p, const DeviceProfile& profile) noexcept;

// Parse + validate raw bytes as the device receives them: a block that does not parse
// (wrong size, reserved bits) is reported as kVersionMismatch (not a block layout the
// device knows).
[[nodiscard]] Validation validate(std::span<const std::uint8_t> block,
                                  const DeviceProfile& profile) noexcept;

}  // namespace rs4sim::profisafe
