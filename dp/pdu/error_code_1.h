#pragma once
// DPV1 Error_Code_1 of a negative response `(Fn|0x80) Error_Decode Error_Code_1
// Error_Code_2` with Error_Decode = 0x80 [IEC 61158-6-3, DPV1 Error_Code_1]: the error
// class in the high nibble, the error code in the low nibble. Carried as std::error_code
// (category "dp.dpv1", message "DPV1 <class> error: <code>"), the shape of lely-core's
// SdoErrc. Any byte is a valid ErrorCode1 (values without a name are reserved or
// user specific); the wire byte is to_wire(e).

#include "codec/error_category.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <system_error>

namespace rs4sim::dp::pdu {

enum class ErrorClass : std::uint8_t {
  kApplication = 0xA,
  kAccess = 0xB,
  kResource = 0xC,
  kUserSpecific = 0xD,  // 0xD..0xF; 0x0..0x9 reserved
};

enum class ErrorCode1 : std::uint8_t {
  kNone = 0x00,  // not an error (e.g. Error_Decode other than DPV1)
  // class 0xA: application
  kReadError = 0xA0,
  kWriteError = 0xA1,
  kModuleFailure = 0xA2,
  kVersionConflict = 0xA8,
  kFeatureNotSupported = 0xA9,
  // class 0xB: access
  kInvalidIndex = 0xB0,
  kWriteLengthError = 0xB1,
  kInvalidSlot = 0xB2,
  kTypeConflict = 0xB3,
  kInvalidArea = 0xB4,
  kStateConflict = 0xB5,
  kAccessDenied = 0xB6,
  kInvalidRange = 0xB7,
  kInvalidParameter = 0xB8,
  kInvalidType = 0xB9,
  // class 0xC: resource
  kReadConstraintConflict = 0xC0,
  kWriteConstraintConflict = 0xC1,
  kResourceBusy = 0xC2,
  kResourceUnavailable = 0xC3,
};

[[nodiscard]] constexpr std::uint8_t to_wire(ErrorCode1 e) noexcept {
  return static_cast<std::uint8_t>(e);
}
[[nodiscard]] constexpr ErrorCode1 error_code_1_from_wire(std::uint8_t byte) noexcept {
  return static_cast<ErrorCode1>(byte);
}
[[nodiscard]] constexpr ErrorClass error_class(ErrorCode1 e) noexcept {
  return static_cast<ErrorClass>(to_wire(e) >> 4U);
}
// The code within its class (low nibble).
[[nodiscard]] constexpr std::uint8_t error_code(ErrorCode1 e) noexcept {
  return static_cast<std::uint8_t>(to_wire(e) & 0x0FU);
}

// "access", "resource", …; "user specific" for 0xD..0xF, "reserved" below 0xA.
[[nodiscard]] std::string_view to_string(ErrorClass c) noexcept;
// "invalid index", …; "user specific or reserved code" for values without a name.
[[nodiscard]] std::string_view to_string(ErrorCode1 e) noexcept;
// "DPV1 access error: state conflict" (the category's message).
[[nodiscard]] std::string error_message(ErrorCode1 e);
constexpr const char* error_category_name(ErrorCode1) noexcept { return "dp.dpv1"; }
inline std::error_code make_error_code(ErrorCode1 e) noexcept {
  return codec::make_error_code_of(e);
}

}  // namespace rs4sim::dp::pdu
