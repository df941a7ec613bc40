#pragma once
// CRC machinery of PROFIsafe ([IEC 61784-3-3 CRC1, CRC2]).
//
// All PROFIsafe CRCs are MSB-first ("non-reflected"), no final XOR; they differ in width,
// polynomial and preset. CRC1 (F_Par_CRC) is VERIFIED against three published blocks;
// the V2 CRC2 (24 bit) is VERIFIED against a real capture (1809 PDUs). The V1 CRC2 rule is
// UNCERTAIN and configurable in pdu.h (Crc2Variant).

#include <array>
#include <cstdint>
#include <optional>
#include <span>

namespace rs4sim::profisafe {

// CRC-16 polynomial of CRC1 and of the 2-byte CRC2 (x^16 + 0x4EAB), [IEC 61784-3-3 CRC1].
inline constexpr std::uint32_t kCrc16Poly = 0x4EAB;
// CRC-24 polynomial of the V2 3-byte CRC2, [IEC 61784-3-3 CRC2] (VERIFIED on the capture).
inline constexpr std::uint32_t kCrc24Poly = 0x5D6DCB;

// CRC-32 polynomial of the V2 4-byte CRC2 (F_CRC_Length 2), [IEC 61784-3-3 CRC2]. No capture or
// published vector here: UNCERTAIN beyond the polynomial (docs/profisafe.md).
inline constexpr std::uint32_t kCrc32Poly = 0xF4ACFB13;

// A table-driven MSB-first CRC of width 16 or 24 (8 < width <= 32, multiple of 8 not
// required). `update` continues from a register value, so a preset is just the start.
class Crc {
 public:
  constexpr Crc(unsigned width, std::uint32_t poly) noexcept;
  [[nodiscard]] std::uint32_t update(std::uint32_t reg,
                                     std::span<const std::uint8_t> data) const noexcept;
  [[nodiscard]] std::uint32_t update_reversed(std::uint32_t reg,
                                              std::span<const std::uint8_t> data) const noexcept;
  [[nodiscard]] constexpr unsigned width() const noexcept { return width_; }
  [[nodiscard]] constexpr std::uint32_t poly() const noexcept { return poly_; }
  [[nodiscard]] constexpr std::uint32_t mask() const noexcept { return mask_; }

 private:
  unsigned width_;
  std::uint32_t poly_;
  std::uint32_t mask_;
  std::array<std::uint32_t, 256> table_{};
};

// The three CRCs PROFIsafe uses, built once.
const Crc& crc16() noexcept;
const Crc& crc24() noexcept;
const Crc& crc32() noexcept;

// CRC1 = F_Par_CRC over the 8 bytes F_Prm_Flag1 .. F_WD_Time (preset 0). When an
// F_iPar_CRC exists, its 4 big-endian bytes are fed first ([IEC 61784-3-3 CRC1], VERIFIED).
[[nodiscard]] std::uint16_t crc1(std::span<const std::uint8_t, 8> block8,
                                 std::optional<std::uint32_t> ipar_crc = std::nullopt) noexcept;

// ----- implementation of the constexpr constructor -----
constexpr Crc::Crc(unsigned width, std::uint32_t poly) noexcept
    : width_(width), poly_(poly), mask_(width >= 32 ? 0xFFFFFFFFu : ((1u << width) - 1u)) {
  const std::uint32_t top = 1u << (width - 1u);
  for (std::uint32_t b = 0; b < 256; ++b) {
    std::uint32_t reg = b << (width - 8u);
    for (int i = 0; i < 8; ++i) {
      reg = (reg & top) != 0 ? ((reg << 1) ^ poly) : (reg << 1);
    }
    table_[b] = reg & mask_;
  }
}

}  // namespace rs4sim::profisafe
