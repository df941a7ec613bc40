#pragma once
// Byte order helpers for values already in hand. Reading and writing a sequence of fields
// goes through codec::Reader / codec::Writer (reader.h, writer.h), which check bounds.

#include <cstdint>

namespace rs4sim::codec {

constexpr std::uint16_t be16(std::uint8_t high, std::uint8_t low) noexcept {
  return static_cast<std::uint16_t>((static_cast<unsigned>(high) << 8U) | low);
}
constexpr std::uint32_t be32(std::uint16_t high, std::uint16_t low) noexcept {
  return (static_cast<std::uint32_t>(high) << 16U) | low;
}
constexpr std::uint8_t high_byte(std::uint16_t v) noexcept {
  return static_cast<std::uint8_t>(v >> 8U);
}
constexpr std::uint8_t low_byte(std::uint16_t v) noexcept {
  return static_cast<std::uint8_t>(v & 0xFFU);
}
// Byte n of v counted from the least significant byte (n = 0..3).
constexpr std::uint8_t byte_of(std::uint32_t v, unsigned n) noexcept {
  return static_cast<std::uint8_t>((v >> (8U * n)) & 0xFFU);
}

}  // namespace rs4sim::codec
