#include "dp/slave/slave_error.h"

namespace rs4sim::dp {

std::string_view to_string(SlaveError e) noexcept {
  switch (e) {
    case SlaveError::kInvalidAddress: return "slave address must be 0..126";
    case SlaveError::kInvalidMaxDiagLength: return "max diagnosis length must be 6..244";
    case SlaveError::kInvalidAlarmCapacity:
      return "alarm capacity must be 1..32 and not exceed the sequence-number range";
    case SlaveError::kInvalidAlarmQueue: return "alarm queue must hold at least one alarm";
    case SlaveError::kInvalidC2Timeout: return "C2 Send_Timeout must be 1..65535 (10 ms)";
    case SlaveError::kInvalidMinTsdr: return "default min TSDR must be at least 11 Tbit";
    case SlaveError::kInvalidAcyclicLength: return "acyclic max data length must be 1..240";
    case SlaveError::kInvalidC2Sap: return "C2 connection SAP must be 0..48";
    case SlaveError::kNoPendingRequest: return "no acyclic request is waiting for completion";
    case SlaveError::kAlarmsClosed: return "alarms are closed (no DPV1 data exchange)";
    case SlaveError::kAlarmTypeNotEnabled: return "alarm type not enabled by the master";
    case SlaveError::kAlarmQueueFull: return "alarm queue full";
    case SlaveError::kInvalidAlarm: return "alarm fields outside the DPV1 ranges";
    case SlaveError::kDiagnosisTooLong: return "device diagnosis longer than 238 bytes";
    case SlaveError::kInvalidDiagnosisBlock: return "device diagnosis blocks malformed";
    case SlaveError::kResponseTooLong: return "acyclic response longer than allowed";
  }
  return "unknown dp.slave error";
}

}  // namespace rs4sim::dp
