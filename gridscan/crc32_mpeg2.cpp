#include "gridscan/crc32_mpeg2.h"

#include <array>

namespace rs4sim::gridscan {
namespace {

constexpr std::array<std::uint32_t, 256> make_table() {
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t b = 0; b < table.size(); ++b) {
    std::uint32_t reg = b << 24U;
    for (int bit = 0; bit < 8; ++bit) {
      reg = (reg & 0x80000000U) != 0 ? (reg << 1U) ^ kCrcPolynomial : reg << 1U;
    }
    table[b] = reg;
  }
  return table;
}

constexpr auto kTable = make_table();

}  // namespace

std::uint32_t crc32_mpeg2_update(std::uint32_t reg, std::span<const std::uint8_t> data) noexcept {
  for (const std::uint8_t b : data) {
    reg = (reg << 8U) ^ kTable[static_cast<std::uint8_t>((reg >> 24U) ^ b)];
  }
  return reg;
}

}  // namespace rs4sim::gridscan
