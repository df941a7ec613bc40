#pragma once
// CRC-16/MODBUS: polynomial 0x8005 reflected (0xA001), init 0xFFFF, no final XOR, check
// value 0x4B37 over "123456789". On the wire the CRC follows the data low byte first
// [Modbus serial line V1.02 §2.5.1.2] [Polaris manual §8.1].

#include <cstdint>
#include <span>

namespace rs4sim::modbus {

[[nodiscard]] std::uint16_t crc16(std::span<const std::uint8_t> bytes) noexcept;

}  // namespace rs4sim::modbus
