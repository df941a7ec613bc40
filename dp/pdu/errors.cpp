#include "dp/pdu/errors.h"

namespace rs4sim::dp::pdu {

std::string_view to_string(PduError e) noexcept {
  switch (e) {
    case PduError::kTooShort: return "PDU shorter than its fixed part";
    case PduError::kTooLong: return "PDU longer than the service allows";
    case PduError::kNotEmpty: return "request must not carry data";
    case PduError::kLengthMismatch: return "length field disagrees with the bytes present";
    case PduError::kBadFunctionCode: return "DPV1 function number not valid here";
    case PduError::kValueOutOfRange: return "field value outside its defined range";
    case PduError::kBadIdentifier: return "malformed configuration identifier";
    case PduError::kBadDiagBlock: return "malformed extended diagnosis block";
    case PduError::kBadAlarm: return "malformed alarm or status PDU";
    case PduError::kBadPrmBlock: return "malformed structured parameter block";
  }
  return "unknown PDU error";
}

}  // namespace rs4sim::dp::pdu
