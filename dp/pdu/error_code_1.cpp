#include "dp/pdu/error_code_1.h"

namespace rs4sim::dp::pdu {

std::string_view to_string(ErrorClass c) noexcept {
  switch (c) {
    case ErrorClass::kApplication: return "application";
    case ErrorClass::kAccess: return "access";
    case ErrorClass::kResource: return "resource";
    case ErrorClass::kUserSpecific: return "user specific";
  }
  return static_cast<std::uint8_t>(c) > 0xD ? "user specific" : "reserved";
}

std::string_view to_string(ErrorCode1 e) noexcept {
  switch (e) {
    case ErrorCode1::kNone: break;
    case ErrorCode1::kReadError: return "read error";
    case ErrorCode1::kWriteError: return "write error";
    case ErrorCode1::kModuleFailure: return "module failure";
    case ErrorCode1::kVersionConflict: return "version conflict";
    case ErrorCode1::kFeatureNotSupported: return "feature not supported";
    case ErrorCode1::kInvalidIndex: return "invalid index";
    case ErrorCode1::kWriteLengthError: return "write length error";
    case ErrorCode1::kInvalidSlot: return "invalid slot";
    case ErrorCode1::kTypeConflict: return "type conflict";
    case ErrorCode1::kInvalidArea: return "invalid area";
    case ErrorCode1::kStateConflict: return "state conflict";
    case ErrorCode1::kAccessDenied: return "access denied";
    case ErrorCode1::kInvalidRange: return "invalid range";
    case ErrorCode1::kInvalidParameter: return "invalid parameter";
    case ErrorCode1::kInvalidType: return "invalid type";
    case ErrorCode1::kReadConstraintConflict: return "read constraint conflict";
    case ErrorCode1::kWriteConstraintConflict: return "write constraint conflict";
    case ErrorCode1::kResourceBusy: return "resource busy";
    case ErrorCode1::kResourceUnavailable: return "resource unavailable";
  }
  return "user specific or reserved code";
}

std::string error_message(ErrorCode1 e) {
  return "DPV1 " + std::string(to_string(error_class(e))) + " error: " + std::string(to_string(e));
}

}  // namespace rs4sim::dp::pdu
