#include "dp/master/master_error.h"

#include <string>

namespace rs4sim::dp::master {
namespace {

const char* master_message(MasterErrc e) {
  switch (e) {
    case MasterErrc::kNoAnswer: return "slave does not answer (slot time expired after all retries)";
    case MasterErrc::kNotASlave: return "station answers FDL_Status as a master, not as a slave";
    case MasterErrc::kSapNotEnabled: return "slave replied RS: service access point not enabled";
    case MasterErrc::kServiceRejected: return "slave rejected the request (UE/RR/negative FDL status)";
    case MasterErrc::kInvalidResponse: return "invalid slave response (SAPs, status, length or PDU)";
    case MasterErrc::kIdentMismatch: return "Ident_Number in Slave_Diag differs from the configuration";
    case MasterErrc::kMasterLock: return "slave is parameterised by another master (Master_Lock)";
    case MasterErrc::kPrmFault: return "slave reports Prm_Fault (Set_Prm rejected)";
    case MasterErrc::kCfgFault: return "slave reports Cfg_Fault (Chk_Cfg rejected)";
    case MasterErrc::kNotSupported: return "slave reports Not_Supported (requested feature)";
    case MasterErrc::kStartupTimeout: return "slave did not become ready for data exchange in time";
    case MasterErrc::kInputLengthMismatch: return "Data_Exchange reply length differs from the input length";
    case MasterErrc::kLeftDataExchange: return "slave left data exchange (Prm_Req/Not_Ready/foreign master)";
    case MasterErrc::kDpv1Negative: return "DPV1 negative response";
    case MasterErrc::kDpv1Timeout: return "DPV1 response timeout";
    case MasterErrc::kDpv1NotEnabled: return "slave is not parameterised for DPV1";
    case MasterErrc::kAborted: return "request aborted: slave left data exchange";
    case MasterErrc::kAlarmAckRejected: return "slave rejected Alarm_Ack";
    case MasterErrc::kAlarmLimitExceeded: return "more outstanding alarms than Alarm_Mode allows";
    case MasterErrc::kAlarmNotOutstanding: return "alarm is not waiting for acknowledgement";
    case MasterErrc::kUnknownSlave: return "no slave with this address is configured";
    case MasterErrc::kNotInDataExchange: return "slave is not in data exchange";
    case MasterErrc::kOutputLengthMismatch: return "output length differs from the configured length";
    case MasterErrc::kBadArgument: return "argument out of range";
    case MasterErrc::kQueueFull: return "request queue of the slave is full";
    case MasterErrc::kBadBusParameters: return "bus parameters violate the FDL timing constraints";
    case MasterErrc::kBadMasterAddress: return "master address must be 0..126";
    case MasterErrc::kBadSlaveConfig: return "invalid slave configuration";
    case MasterErrc::kDuplicateSlave: return "slave address configured twice or equal to the master";
  }
  return "unknown master error";
}

class MasterCategory final : public std::error_category {
 public:
  const char* name() const noexcept override { return "dp.master"; }
  std::string message(int v) const override {
    return master_message(static_cast<MasterErrc>(v));
  }
};

const char* dpv1_class_name(std::uint8_t cls) {
  switch (cls) {
    case 0xA: return "application";
    case 0xB: return "access";
    case 0xC: return "resource";
    case 0xD: return "user specific";
    default: return "reserved";
  }
}

const char* dpv1_code_name(std::uint8_t code1) {
  namespace c = pdu::error_code_1;
  switch (code1) {
    case c::kReadError: return "read error";
    case c::kWriteError: return "write error";
    case c::kModuleFailure: return "module failure";
    case c::kVersionConflict: return "version conflict";
    case c::kFeatureNotSupported: return "feature not supported";
    case c::kInvalidIndex: return "invalid index";
    case c::kWriteLengthError: return "write length error";
    case c::kInvalidSlot: return "invalid slot";
    case c::kTypeConflict: return "type conflict";
    case c::kInvalidArea: return "invalid area";
    case c::kStateConflict: return "state conflict";
    case c::kAccessDenied: return "access denied";
    case c::kInvalidRange: return "invalid range";
    case c::kInvalidParameter: return "invalid parameter";
    case c::kInvalidType: return "invalid type";
    case c::kReadConstraintConflict: return "read constraint conflict";
    case c::kWriteConstraintConflict: return "write constraint conflict";
    case c::kResourceBusy: return "resource busy";
    case c::kResourceUnavailable: return "resource unavailable";
    default: return "user specific or reserved code";
  }
}

class Dpv1Category final : public std::error_category {
 public:
  const char* name() const noexcept override { return "dp.dpv1"; }
  std::string message(int v) const override {
    const auto code1 = static_cast<std::uint8_t>(v);
    return std::string("DPV1 ") + dpv1_class_name(static_cast<std::uint8_t>(code1 >> 4)) +
           " error: " + dpv1_code_name(code1);
  }
};

}  // namespace

const std::error_category& error_category() noexcept {
  static const MasterCategory category;
  return category;
}

std::error_code make_error_code(MasterErrc e) noexcept {
  return {static_cast<int>(e), error_category()};
}

const std::error_category& dpv1_error_category() noexcept {
  static const Dpv1Category category;
  return category;
}

std::error_code to_error_code(const pdu::Dpv1Error& e) noexcept {
  if (e.error_decode == pdu::error_decode::kDpv1 && e.error_code_1 != 0) return {e.error_code_1, dpv1_error_category()};
  return make_error_code(MasterErrc::kDpv1Negative);
}

}  // namespace rs4sim::dp::master
