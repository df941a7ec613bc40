#include "dp/master/master_error.h"

namespace rs4sim::dp::master {

std::string_view to_string(MasterError e) noexcept {
  switch (e) {
    case MasterError::kNoAnswer:
      return "slave does not answer (slot time expired after all retries)";
    case MasterError::kNotASlave: return "station answers FDL_Status as a master, not as a slave";
    case MasterError::kSapNotEnabled: return "slave replied RS: service access point not enabled";
    case MasterError::kServiceRejected:
      return "slave rejected the request (UE/RR/negative FDL status)";
    case MasterError::kInvalidResponse:
      return "invalid slave response (SAPs, status, length or PDU)";
    case MasterError::kIdentMismatch:
      return "Ident_Number in Slave_Diag differs from the configuration";
    case MasterError::kMasterLock: return "slave is parameterised by another master (Master_Lock)";
    case MasterError::kPrmFault: return "slave reports Prm_Fault (Set_Prm rejected)";
    case MasterError::kCfgFault: return "slave reports Cfg_Fault (Chk_Cfg rejected)";
    case MasterError::kNotSupported: return "slave reports Not_Supported (requested feature)";
    case MasterError::kStartupTimeout:
      return "slave did not become ready for data exchange in time";
    case MasterError::kInputLengthMismatch:
      return "Data_Exchange reply length differs from the input length";
    case MasterError::kLeftDataExchange:
      return "slave left data exchange (Prm_Req/Not_Ready/foreign master)";
    case MasterError::kDpv1Negative: return "DPV1 negative response";
    case MasterError::kDpv1Timeout: return "DPV1 response timeout";
    case MasterError::kDpv1NotEnabled: return "slave is not parameterised for DPV1";
    case MasterError::kAborted: return "request aborted: slave left data exchange";
    case MasterError::kAlarmAckRejected: return "slave rejected Alarm_Ack";
    case MasterError::kAlarmLimitExceeded: return "more outstanding alarms than Alarm_Mode allows";
    case MasterError::kAlarmNotOutstanding: return "alarm is not waiting for acknowledgement";
    case MasterError::kUnknownSlave: return "no slave with this address is configured";
    case MasterError::kNotInDataExchange: return "slave is not in data exchange";
    case MasterError::kOutputLengthMismatch:
      return "output length differs from the configured length";
    case MasterError::kBadArgument: return "argument out of range";
    case MasterError::kQueueFull: return "request queue of the slave is full";
    case MasterError::kBadBusParameters: return "bus parameters violate the FDL timing constraints";
    case MasterError::kBadMasterAddress: return "master address must be 0..126";
    case MasterError::kBadSlaveConfig: return "invalid slave configuration";
    case MasterError::kDuplicateSlave:
      return "slave address configured twice or equal to the master";
  }
  return "unknown master error";
}

std::error_code to_error_code(const pdu::Dpv1Error& e) noexcept {
  if (e.error_decode == pdu::error_decode::kDpv1 && e.error_code_1 != pdu::ErrorCode1::kNone) {
    return make_error_code(e.error_code_1);
  }
  return make_error_code(MasterError::kDpv1Negative);
}

}  // namespace rs4sim::dp::master
