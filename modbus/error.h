#pragma once
// Why a byte sequence is not a usable Modbus RTU frame or PDU.

#include "codec/error_category.h"

#include <cstdint>
#include <string_view>
#include <system_error>

namespace rs4sim::modbus {

enum class ModbusError : std::uint8_t {
  kTooShort = 1,   // fewer than 4 bytes (address, function, CRC)
  kTooLong,        // more than 256 bytes [Modbus serial line V1.02 §2.5.1]
  kBadCrc,         // the CRC does not match the bytes before it
  kBadLength,      // the PDU's length does not fit its function
  kBadByteCount,   // a byte count disagrees with the word count or the frame length
  kBadQuantity,    // a register count outside 1..125 (read) or 1..123 (write)
  kWrongFunction,  // the PDU is not the function the caller asked to decode
};

[[nodiscard]] std::string_view to_string(ModbusError e) noexcept;
constexpr const char* error_category_name(ModbusError) noexcept { return "modbus"; }
inline std::error_code make_error_code(ModbusError e) noexcept {
  return codec::make_error_code_of(e);
}

}  // namespace rs4sim::modbus
