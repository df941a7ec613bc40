#pragma once
// Errors the slave core reports to its owner and to the application (not wire errors:
// on the wire the slave answers as [IEC 61158-6-3 DP-V0 services, DPV1] prescribe).
// Carried as std::error_code with the category "dp.slave".

#include "codec/error_category.h"

#include <cstdint>
#include <string_view>
#include <system_error>

namespace rs4sim::dp {

enum class SlaveError : std::uint8_t {
  // SlaveConfig::validate()
  kInvalidAddress = 1,    // station address outside 0…126 ([IEC 61158-4-3 addresses, SAPs])
  kInvalidMaxDiagLength,  // max diag length outside 6…244 ([IEC 61158-6-3 Slave_Diag])
  kInvalidAlarmCapacity,  // alarm count outside 1…32 or > sequence numbers
                          // ([IEC 61158-6-3 DPV1 alarms])
  kInvalidAlarmQueue,     // alarm queue shorter than 1
  kInvalidC2Timeout,      // C2 RM Send_Timeout 0 (unit 10 ms, 1…65535, [IEC 61158-6-3 MSAC_C2])
  kInvalidMinTsdr,        // default min TSDR below 11 Tbit ([IEC 61158-4-3 bus parameters, timing])
  kInvalidAcyclicLength,  // C1/C2 max data length outside 1…240 ([IEC 61158-6-3 MSAC_C1])
  kInvalidC2Sap,          // C2 connection SAP outside 0…48 ([IEC 61158-6-3 MSAC_C2])
  // SlaveControl calls from the application
  kNoPendingRequest,       // complete_acyclic() without an outstanding request
  kAlarmsClosed,           // alarms not open (no DPV1 data exchange, [IEC 61158-6-3 MSAC_C1])
  kAlarmTypeNotEnabled,    // the master did not enable this alarm type (DPV1_Status_2)
  kAlarmQueueFull,         // more alarms submitted than the queue holds
  kInvalidAlarm,           // alarm type/slot/specifier/data outside [IEC 61158-6-3 DPV1 alarms]
  kDiagnosisTooLong,       // device diagnosis longer than 238 bytes ([IEC 61158-6-3 Slave_Diag])
  kInvalidDiagnosisBlock,  // device diagnosis blocks do not parse as [IEC 61158-6-3 Slave_Diag]
                           // blocks
  kResponseTooLong,        // acyclic read data longer than requested / 240 bytes
};

[[nodiscard]] std::string_view to_string(SlaveError e) noexcept;
constexpr const char* error_category_name(SlaveError) noexcept { return "dp.slave"; }
inline std::error_code make_error_code(SlaveError e) noexcept {
  return codec::make_error_code_of(e);
}

}  // namespace rs4sim::dp
