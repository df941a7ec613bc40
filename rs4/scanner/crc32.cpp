#include "rs4/scanner/crc32.h"

#include <array>

namespace rs4sim::rs4::scanner {
namespace {

constexpr std::array<std::uint32_t, 256> make_table() {
  std::array<std::uint32_t, 256> t{};
  for (std::uint32_t i = 0; i < 256; ++i) {
    std::uint32_t c = i;
    for (int k = 0; k < 8; ++k) c = (c & 1U) != 0 ? (c >> 1) ^ 0xEDB88320U : c >> 1;
    t[i] = c;
  }
  return t;
}
constexpr auto kTable = make_table();

}  // namespace

std::uint32_t crc32_iso_hdlc(std::span<const std::uint8_t> bytes) noexcept {
  std::uint32_t crc = 0xFFFFFFFFU;
  for (const std::uint8_t b : bytes) crc = (crc >> 8) ^ kTable[(crc ^ b) & 0xFFU];
  return crc ^ 0xFFFFFFFFU;
}

}  // namespace rs4sim::rs4::scanner
