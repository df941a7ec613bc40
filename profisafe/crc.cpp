// CRC machinery ([IEC 61784-3-3 CRC1, CRC2]). See crc.h.
#include "profisafe/crc.h"

#include "codec/writer.h"

namespace rs4sim::profisafe {

std::uint32_t Crc::update(std::uint32_t reg, std::span<const std::uint8_t> data) const noexcept {
  const unsigned shift = width_ - 8u;
  for (const std::uint8_t b : data) {
    const auto index = static_cast<std::uint8_t>((reg >> shift) ^ b);
    reg = ((reg << 8) ^ table_[index]) & mask_;
  }
  return reg;
}

std::uint32_t Crc::update_reversed(std::uint32_t reg,
                                   std::span<const std::uint8_t> data) const noexcept {
  const unsigned shift = width_ - 8u;
  for (auto it = data.rbegin(); it != data.rend(); ++it) {
    const auto index = static_cast<std::uint8_t>((reg >> shift) ^ *it);
    reg = ((reg << 8) ^ table_[index]) & mask_;
  }
  return reg;
}

namespace {
constexpr Crc kCrc16{16, kCrc16Poly};
constexpr Crc kCrc24{24, kCrc24Poly};
constexpr Crc kCrc32{32, kCrc32Poly};
}  // namespace

const Crc& crc16() noexcept { return kCrc16; }
const Crc& crc24() noexcept { return kCrc24; }
const Crc& crc32() noexcept { return kCrc32; }

std::uint16_t crc1(std::span<const std::uint8_t, 8> block8,
                   std::optional<std::uint32_t> ipar_crc) noexcept {
  std::uint32_t reg = 0;
  if (ipar_crc) {
    // [IEC 61784-3-3 CRC1]: the F_iPar_CRC's big-endian bytes come first (VERIFIED vector 3).
    std::array<std::uint8_t, 4> ipar{};
    codec::Writer(ipar).u32_be(*ipar_crc);
    reg = kCrc16.update(reg, ipar);
  }
  return static_cast<std::uint16_t>(kCrc16.update(reg, block8));
}

}  // namespace rs4sim::profisafe
