#pragma once
// The cyclic process bytes of the RS4/PROFIsafe ([RS4 manual §5.1])
// and the PROFIBUS address switches ([RS4 manual §4.5]). Pure functions, no state.

#include "codec/error_category.h"

#include <boost/outcome/std_result.hpp>

#include <cstdint>
#include <string_view>
#include <system_error>

namespace rs4sim::rs4::adapter {

// ---- input byte, device → master ([RS4 manual §5.1.1]) ----------------------------------
inline constexpr std::uint8_t kInputOssd = 0x80;             // bit 7: the only safety bit
inline constexpr std::uint8_t kInputWarningOutputN = 0x40;   // bit 6: inverted warning output
inline constexpr std::uint8_t kInputError = 0x20;            // bit 5
inline constexpr std::uint8_t kInputOperatingState = 0x10;   // bit 4: 1 = not protecting
inline constexpr std::uint8_t kInputRs232Active = 0x08;      // bit 3
inline constexpr std::uint8_t kInputProxyRequest = 0x04;     // bit 2
inline constexpr std::uint8_t kInputProtectiveField = 0x02;  // bit 1
inline constexpr std::uint8_t kInputWarningField = 0x01;     // bit 0

struct InputBits {
  bool ossd = false;
  bool warning_output_active = false;  // on the wire inverted: bit 6 = 0 when active
  bool error = false;
  bool not_operational = false;  // bit 4: configuration, initialisation or check pending
  bool rs232_active = false;
  bool proxy_request = false;
  bool protective_field = false;
  bool warning_field = false;
  friend bool operator==(const InputBits&, const InputBits&) = default;
};
[[nodiscard]] InputBits decode_input_byte(std::uint8_t byte) noexcept;
// Bit 7 is taken from `bits.ossd` as given: the adapter's safety rule lives in
// Adapter::compose_input_byte, which alone decides the value it passes here.
[[nodiscard]] std::uint8_t encode_input_byte(const InputBits& bits) noexcept;

// ---- output byte, master → device ([RS4 manual §5.1.2]) ---------------------------------
inline constexpr std::uint8_t kOutputRestart = 0x80;      // bit 7
inline constexpr std::uint8_t kOutputProxyEnable = 0x40;  // bit 6
inline constexpr std::uint8_t kOutputReserved = 0x38;     // bits 5..3, expected 0
inline constexpr std::uint8_t kOutputFieldPair = 0x07;    // bits 2..0: 1..4

struct OutputBits {
  bool restart = false;
  bool proxy_enable = false;
  std::uint8_t reserved = 0;    // bits 5..3 as received (ignored)
  std::uint8_t field_pair = 0;  // raw bits 2..0
  [[nodiscard]] bool field_pair_valid() const noexcept {
    return field_pair >= 1 && field_pair <= 4;
  }
  friend bool operator==(const OutputBits&, const OutputBits&) = default;
};
[[nodiscard]] OutputBits decode_output_byte(std::uint8_t byte) noexcept;
[[nodiscard]] std::uint8_t encode_output_byte(const OutputBits& bits) noexcept;

// ---- address switches ([RS4 manual §4.5]) ----------------------------------------------------
struct AddressSwitches {
  std::uint8_t hex_high = 0x0;  // HexH: high nibble (0..F)
  std::uint8_t hex_low = 0x4;   // HexL: low nibble (0..F); factory setting 4
  friend bool operator==(const AddressSwitches&, const AddressSwitches&) = default;
};
enum class AddressError : std::uint8_t {
  kReservedAddress = 1,  // 127 (0x7F) or 255 (0xFF): must not be used ([RS4 manual §4.5])
  kNibbleOutOfRange,     // a switch value above 0xF
};
[[nodiscard]] std::string_view to_string(AddressError e) noexcept;
constexpr const char* error_category_name(AddressError) noexcept { return "rs4.address"; }
inline std::error_code make_error_code(AddressError e) noexcept {
  return codec::make_error_code_of(e);
}

// Station address 0..126: bit 7 of the switch value is not evaluated.
boost::outcome_v2::std_result<std::uint8_t> station_address(AddressSwitches s) noexcept;

}  // namespace rs4sim::rs4::adapter
