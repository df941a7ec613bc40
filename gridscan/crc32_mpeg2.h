#pragma once
// CRC-32/MPEG-2 of the CEDES protocol ([GridScan manual §9.2.5, §10.2.2]): polynomial
// 0x04C11DB7, initial value 0xFFFFFFFF, no reflection of input or output, no final XOR.
// Check value over "123456789": 0x0376E6E7. (The manual's "according to IEEE 802.3" names
// only the polynomial: the reflected Ethernet CRC does not reproduce its examples.)

#include <cstdint>
#include <span>

namespace rs4sim::gridscan {

inline constexpr std::uint32_t kCrcPolynomial = 0x04C11DB7;
inline constexpr std::uint32_t kCrcInitial = 0xFFFFFFFF;

// Continues a CRC register over `data` (MSB first); start with kCrcInitial.
[[nodiscard]] std::uint32_t crc32_mpeg2_update(std::uint32_t reg,
                                               std::span<const std::uint8_t> data) noexcept;

[[nodiscard]] inline std::uint32_t crc32_mpeg2(std::span<const std::uint8_t> data) noexcept {
  return crc32_mpeg2_update(kCrcInitial, data);
}

}  // namespace rs4sim::gridscan
