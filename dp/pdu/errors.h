#pragma once
// Typed decode/encode errors of the DP and DPV1 service PDUs
// ([IEC 61158-6-3 DP-V0 services, DPV1]). Carried as std::error_code with the category "dp.pdu";
// decoders return pdu::Result<T> = boost::outcome_v2::std_result<T>.

#include "codec/error_category.h"

#include <boost/outcome/std_result.hpp>
#include <boost/outcome/try.hpp>

#include <cstdint>
#include <string_view>
#include <system_error>

namespace rs4sim::dp::pdu {

enum class PduError : std::uint8_t {
  kTooShort = 1,     // DU shorter than the service's fixed part
  kTooLong,          // DU longer than the service allows (e.g. Set_Prm > 244)
  kNotEmpty,         // request that must be empty carries data (Slave_Diag, Get_Cfg…)
  kLengthMismatch,   // a length field disagrees with the bytes present
  kBadFunctionCode,  // DPV1 function number unknown or not valid here ([IEC 61158-6-3 MSAC_C1])
  kValueOutOfRange,  // a field outside its defined range (address, slot, length…)
  kBadIdentifier,    // Chk_Cfg/Get_Cfg identifier malformed ([IEC 61158-6-3 Chk_Cfg/Get_Cfg])
  kBadDiagBlock,     // extended diagnosis block header/length malformed
                     // ([IEC 61158-6-3 Slave_Diag])
  kBadAlarm,         // alarm/status PDU malformed ([IEC 61158-6-3 DPV1 alarms, status PDUs])
  kBadPrmBlock,      // structured parameter block length malformed
                     // ([IEC 61158-6-3 structured Prm_Data])
};

[[nodiscard]] std::string_view to_string(PduError e) noexcept;
constexpr const char* error_category_name(PduError) noexcept { return "dp.pdu"; }
inline std::error_code make_error_code(PduError e) noexcept { return codec::make_error_code_of(e); }

template <class T>
using Result = boost::outcome_v2::std_result<T>;

}  // namespace rs4sim::dp::pdu
