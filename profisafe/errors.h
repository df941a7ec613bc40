#pragma once
// Typed errors of the PROFIsafe layer ([docs/design.md#error-codes]): wire-level decode failures
// and per-PDU check failures, carried as std::error_code with the "rs4sim.profisafe" category.
// Refused F-parameters are not errors of this kind: see FParameterFault in f_parameters.h.

#include "codec/error_category.h"

#include <cstdint>
#include <string_view>
#include <system_error>
#include <type_traits>

namespace rs4sim::profisafe {

enum class ProfisafeError : std::uint8_t {
  kOk = 0,
  // F-parameter block ([IEC 61784-3-3 F-Parameters])
  kFParamsWrongSize = 1,       // the block is not exactly 10 bytes
  kFParamsReservedBits = 2,    // F_Prm_Flag1 b6-7 or F_Prm_Flag2 b0-2 are not 0
  kFParamsIParCrcNeedsV2 = 3,  // an F_iPar_CRC only exists in V2 blocks
  // safety PDU ([PROFIsafe V1.30 safety PDU] [IEC 61784-3-3 CRC2])
  kPduWrongSize = 10,             // the PDU length does not match data length + overhead
  kPduCrc2Mismatch = 11,          // CRC2 check failed (CE_CRC)
  kPduConsecutiveNumber = 12,     // consecutive number not the expected one
  kPduUnsupportedCrcLength = 13,  // the configuration asks for a CRC2 size not implemented
  kPduDataTooLong = 14,           // more F-data than the CRC length allows
  // F-device / F-host state
  kNotParameterised = 20,  // no valid F-parameters yet
};

[[nodiscard]] std::string_view to_string(ProfisafeError e) noexcept;
constexpr const char* error_category_name(ProfisafeError) noexcept { return "rs4sim.profisafe"; }
inline std::error_code make_error_code(ProfisafeError e) noexcept {
  return codec::make_error_code_of(e);
}
inline const std::error_category& profisafe_category() noexcept {
  return codec::category_of<ProfisafeError>();
}

}  // namespace rs4sim::profisafe

template <>
struct std::is_error_code_enum<rs4sim::profisafe::ProfisafeError> : std::true_type {};
