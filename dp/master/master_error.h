#pragma once
// Typed errors of the class 1 master
// ([IEC 61158-6-3 master start-up of a slave, slave supervision, MSAC_C1, DPV1 alarms]
// [pyprofibus dp_master.py]). Carried as std::error_code with the category
// master::error_category().

#include "codec/error_category.h"
#include "dp/pdu/dpv1.h"

#include <cstdint>
#include <string_view>
#include <system_error>

namespace rs4sim::dp::master {

enum class MasterError : std::uint8_t {
  // Per-slave start-up and supervision
  // ([IEC 61158-6-3 master start-up of a slave, slave supervision] [pyprofibus dp_master.py]).
  kNoAnswer = 1,         // no reply within TSL after max_retry_limit retries
  kNotASlave,            // FDL_Status reply shows a master station type
                         // ([IEC 61158-4-3 frame control])
  kSapNotEnabled,        // reply RS: service/SAP not activated (slave left DATA_EXCH)
  kServiceRejected,      // reply UE/RR or another negative FDL status
  kInvalidResponse,      // well-formed telegram with wrong SAPs, status, length or PDU
  kIdentMismatch,        // Ident_Number in Slave_Diag differs from the configuration
  kMasterLock,           // Diag.Master_Add names another master
                         // ([IEC 61158-6-3 master start-up of a slave] [pyprofibus dp_master.py]
                         // step 1)
  kPrmFault,             // Station_Status_1 bit 6 after Set_Prm
  kCfgFault,             // Station_Status_1 bit 2 after Chk_Cfg
  kNotSupported,         // Station_Status_1 bit 4 (feature requested in Set_Prm/GC)
  kStartupTimeout,       // Slave_Diag did not become ready within ready_timeout
  kInputLengthMismatch,  // Data_Exchange reply length ≠ configured input length
  kLeftDataExchange,     // diag shows Prm_Req/Not_Ready/foreign master during DX
                         // ([IEC 61158-6-3 slave supervision])
  // DPV1 C1 client ([IEC 61158-6-3 MSAC_C1, MSAC_C1 polling]) and alarms
  // ([IEC 61158-6-3 DPV1 alarms]).
  kDpv1Negative,         // negative response; details in Dpv1Error
  kDpv1Timeout,          // no response PDU within the C1 response timeout
  kDpv1NotEnabled,       // slave not parameterised with DPV1_Enable
  kAborted,              // request dropped because the slave left data exchange
  kAlarmAckRejected,     // negative Alarm_Ack response (0xDC)
  kAlarmLimitExceeded,   // more outstanding alarms than Alarm_Mode allows
  kAlarmNotOutstanding,  // user acknowledged an alarm that is not waiting for ack
  // User API misuse.
  kUnknownSlave,
  kNotInDataExchange,
  kOutputLengthMismatch,
  kBadArgument,  // slot/index/length/command out of range
  kQueueFull,
  // Configuration (validated once).
  kBadBusParameters,
  kBadMasterAddress,
  kBadSlaveConfig,
  kDuplicateSlave,
};

[[nodiscard]] std::string_view to_string(MasterError e) noexcept;
constexpr const char* error_category_name(MasterError) noexcept { return "dp.master"; }
inline std::error_code make_error_code(MasterError e) noexcept {
  return codec::make_error_code_of(e);
}
inline const std::error_category& error_category() noexcept {
  return codec::category_of<MasterError>();
}

// Category whose values are DPV1 Error_Code_1 bytes ([IEC 61158-6-3 MSAC_C1]: class in the high
// nibble, code in the low nibble; pdu::ErrorCode1). Messages name class and code.
inline const std::error_category& dpv1_error_category() noexcept {
  return codec::category_of<pdu::ErrorCode1>();
}

// The std::error_code of a negative response: Error_Code_1 in dpv1_error_category() when
// Error_Decode = 0x80 (DPV1) and Error_Code_1 ≠ 0; otherwise MasterError::kDpv1Negative.
// The complete bytes stay available in the result (pdu::Dpv1Error).
std::error_code to_error_code(const pdu::Dpv1Error& e) noexcept;

}  // namespace rs4sim::dp::master
