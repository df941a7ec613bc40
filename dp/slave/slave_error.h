#pragma once
// Errors the slave core reports to its owner and to the application (not wire errors:
// on the wire the slave answers as spec/profibus-dp.md §2/§3 prescribe).
// Carried as std::error_code with the category "dp.slave".

#include "codec/error_category.h"

#include <cstdint>
#include <string_view>
#include <system_error>

namespace rs4sim::dp {

enum class SlaveError : std::uint8_t {
  // SlaveConfig::validate()
  kInvalidAddress = 1,        // station address outside 0…126 (§1.4)
  kInvalidMaxDiagLength,      // max diag length outside 6…244 (§2.5)
  kInvalidAlarmCapacity,      // alarm count outside 1…32 or > sequence numbers (§3.5)
  kInvalidAlarmQueue,         // alarm queue shorter than 1
  kInvalidC2Timeout,          // C2 RM Send_Timeout 0 (unit 10 ms, 1…65535, §3.7)
  kInvalidMinTsdr,            // default min TSDR below 11 Tbit (§1.7)
  kInvalidAcyclicLength,      // C1/C2 max data length outside 1…240 (§3.3)
  kInvalidC2Sap,              // C2 connection SAP outside 0…48 (§3.7)
  // SlaveControl calls from the application
  kNoPendingRequest,          // complete_acyclic() without an outstanding request
  kAlarmsClosed,              // alarms not open (no DPV1 data exchange, §3.3)
  kAlarmTypeNotEnabled,       // the master did not enable this alarm type (DPV1_Status_2)
  kAlarmQueueFull,            // more alarms submitted than the queue holds
  kInvalidAlarm,              // alarm type/slot/specifier/data outside §3.5
  kDiagnosisTooLong,          // device diagnosis longer than 238 bytes (§2.5)
  kInvalidDiagnosisBlock,     // device diagnosis blocks do not parse as §2.5 blocks
  kResponseTooLong,           // acyclic read data longer than requested / 240 bytes
};

[[nodiscard]] std::string_view to_string(SlaveError e) noexcept;
constexpr const char* error_category_name(SlaveError) noexcept { return "dp.slave"; }
inline std::error_code make_error_code(SlaveError e) noexcept { return codec::make_error_code_of(e); }

}  // namespace rs4sim::dp

template <>
struct std::is_error_code_enum<rs4sim::dp::SlaveError> : std::true_type {};
