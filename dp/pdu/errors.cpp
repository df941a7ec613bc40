#include "dp/pdu/errors.h"

#include <string>

namespace rs4sim::dp::pdu {
namespace {

class PduCategory final : public std::error_category {
 public:
  [[nodiscard]] const char* name() const noexcept override { return "dp.pdu"; }
  [[nodiscard]] std::string message(int ev) const override {
    switch (static_cast<PduError>(ev)) {
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
    return "unknown PDU error " + std::to_string(ev);
  }
};

}  // namespace

const std::error_category& pdu_category() noexcept {
  static const PduCategory category;
  return category;
}

std::error_code make_error_code(PduError e) noexcept { return {static_cast<int>(e), pdu_category()}; }

}  // namespace rs4sim::dp::pdu
