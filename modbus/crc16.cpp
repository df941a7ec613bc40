#include "modbus/crc16.h"

namespace rs4sim::modbus {

std::uint16_t crc16(std::span<const std::uint8_t> bytes) noexcept {
  constexpr std::uint16_t kPolyReflected = 0xA001;
  std::uint16_t crc = 0xFFFF;
  for (const std::uint8_t b : bytes) {
    crc = static_cast<std::uint16_t>(crc ^ b);
    for (int bit = 0; bit < 8; ++bit) {
      const bool lsb = (crc & 1U) != 0;
      crc = static_cast<std::uint16_t>(crc >> 1U);
      if (lsb) crc = static_cast<std::uint16_t>(crc ^ kPolyReflected);
    }
  }
  return crc;
}

}  // namespace rs4sim::modbus
