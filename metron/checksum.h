#pragma once
// The METRON's checksum: "the complement to 1 of the sum of the bytes in the Command and
// Data fields" [METRON manual "No node"], and in standard line mode of "the bytes of the
// data fields only" [METRON manual "With control checksum"]. The manual does not say
// whether the sum is taken modulo 256 or as a one's-complement (end-around-carry) sum; the
// two differ only when the bytes add up to more than 255. DECISION: modulo 256 by default,
// the other reading selectable ([docs/metron.md#checksum]).

#include <cstdint>
#include <span>
#include <string_view>

namespace rs4sim::metron {

enum class ChecksumReading : std::uint8_t {
  kModulo256,      // ~(sum mod 256): sum(bytes) + checksum == 0xFF (mod 256)
  kEndAroundCarry  // ~(one's-complement sum): each carry out of bit 7 is added back in
};

[[nodiscard]] std::uint8_t checksum(std::span<const std::uint8_t> bytes, ChecksumReading reading);

[[nodiscard]] std::string_view to_string(ChecksumReading r);

}  // namespace rs4sim::metron
