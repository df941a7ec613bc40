#pragma once
// The RS4's F-parameter diagnosis numbers [RS4 manual §6.3, table 6.3-1]: byte 11 of the
// status PDU `05 81 00 00 nn` it reports after the 6 standard diagnosis bytes. The RS4
// numbers the generic F-parameter faults (profisafe::FParameterFault) its own way: the
// PROFIsafe code 64 "F_Dest_Add mismatch" is not in its table, a wrong F_Dest_Add is 66.

#include "codec/error_category.h"
#include "profisafe/f_parameters.h"

#include <array>
#include <cstdint>
#include <string>
#include <system_error>
#include <type_traits>

namespace rs4sim::rs4::safety {

enum class FDiagnosis : std::uint8_t {
  kNone = 0,                       // 0  = Kein Fehler
  kInternalDestAdd = 65,           // 65 = Interner Fehler bei F_Dest_Add
  kWrongDestAdd = 66,              // 66 = Falsche F_Dest_Add
  kWrongSourceAdd = 67,            // 67 = Falsche F_Source_Add
  kWrongWdTime = 68,               // 68 = Falsche F_WD_Time Einstellung
  kWrongSil = 69,                  // 69 = Falsche SIL Einstellung
  kWrongCrcLength = 70,            // 70 = Falsche CRC Laenge
  kWrongBlockIdOrParVersion = 71,  // 71 = Falsche F_Block_ID oder F_Par_Version
  kWrongCrc1 = 72,                 // 72 = Falsche CRC1 ueber die F-Parameter
};

// The RS4's number for a generic F-parameter fault.
[[nodiscard]] FDiagnosis diagnosis(profisafe::FParameterFault fault) noexcept;
[[nodiscard]] const char* to_string(FDiagnosis d) noexcept;

// The 5 bytes after the 6 standard diagnosis bytes [RS4 manual §6.3, bytes 7..11]:
// length 5, type 0x81 status message, slot 0, no differentiation, error number.
[[nodiscard]] std::array<std::uint8_t, 5> status_pdu(FDiagnosis d) noexcept;

// "66 F_Dest_Add mismatch": the number, then the fault (the category's message).
[[nodiscard]] std::string error_message(FDiagnosis d);
constexpr const char* error_category_name(FDiagnosis) noexcept { return "rs4sim.rs4.fdiagnosis"; }
inline std::error_code make_error_code(FDiagnosis d) noexcept {
  return codec::make_error_code_of(d);
}
inline const std::error_category& fdiagnosis_category() noexcept {
  return codec::category_of<FDiagnosis>();
}

}  // namespace rs4sim::rs4::safety
