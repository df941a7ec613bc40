#include "rs4/adapter/cyclic_bytes.h"

#include <string>

namespace rs4sim::rs4::adapter {

InputBits decode_input_byte(std::uint8_t b) noexcept {
  InputBits bits;
  bits.ossd = (b & kInputOssd) != 0;
  bits.warning_output_active = (b & kInputWarningOutputN) == 0;  // [RS4 manual §5.1.1]: inverted
  bits.error = (b & kInputError) != 0;
  bits.not_operational = (b & kInputOperatingState) != 0;
  bits.rs232_active = (b & kInputRs232Active) != 0;
  bits.proxy_request = (b & kInputProxyRequest) != 0;
  bits.protective_field = (b & kInputProtectiveField) != 0;
  bits.warning_field = (b & kInputWarningField) != 0;
  return bits;
}

std::uint8_t encode_input_byte(const InputBits& bits) noexcept {
  std::uint8_t b = 0;
  if (bits.ossd) b |= kInputOssd;
  if (!bits.warning_output_active) b |= kInputWarningOutputN;
  if (bits.error) b |= kInputError;
  if (bits.not_operational) b |= kInputOperatingState;
  if (bits.rs232_active) b |= kInputRs232Active;
  if (bits.proxy_request) b |= kInputProxyRequest;
  if (bits.protective_field) b |= kInputProtectiveField;
  if (bits.warning_field) b |= kInputWarningField;
  return b;
}

OutputBits decode_output_byte(std::uint8_t b) noexcept {
  return OutputBits{(b & kOutputRestart) != 0, (b & kOutputProxyEnable) != 0,
                    static_cast<std::uint8_t>((b & kOutputReserved) >> 3),
                    static_cast<std::uint8_t>(b & kOutputFieldPair)};
}

std::uint8_t encode_output_byte(const OutputBits& bits) noexcept {
  std::uint8_t b = static_cast<std::uint8_t>(bits.field_pair & kOutputFieldPair);
  b |= static_cast<std::uint8_t>((bits.reserved << 3) & kOutputReserved);
  if (bits.restart) b |= kOutputRestart;
  if (bits.proxy_enable) b |= kOutputProxyEnable;
  return b;
}

std::string_view to_string(AddressError e) noexcept {
  switch (e) {
    case AddressError::kReservedAddress:
      return "address switches give 127: reserved, must not be used ([RS4 manual §4.5])";
    case AddressError::kNibbleOutOfRange: return "hex switch value above 0xF";
  }
  return "unknown address error";
}

boost::outcome_v2::std_result<std::uint8_t> station_address(AddressSwitches s) noexcept {
  if (s.hex_high > 0xF || s.hex_low > 0xF) return make_error_code(AddressError::kNibbleOutOfRange);
  // [RS4 manual §4.5]: bit 7 (HexH bit 3) is not evaluated; 127 and 255 must not be used.
  const auto value = static_cast<std::uint8_t>(((s.hex_high << 4) | s.hex_low) & 0x7F);
  if (value == 0x7F) return make_error_code(AddressError::kReservedAddress);
  return value;
}

}  // namespace rs4sim::rs4::adapter
