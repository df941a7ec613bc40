#include "metron/checksum.h"

namespace rs4sim::metron {

std::uint8_t checksum(std::span<const std::uint8_t> bytes, ChecksumReading reading) {
  unsigned sum = 0;
  for (const auto b : bytes) {
    sum += b;
    if (reading == ChecksumReading::kEndAroundCarry && sum > 0xFFU) sum = (sum & 0xFFU) + 1U;
  }
  return static_cast<std::uint8_t>(~sum & 0xFFU);
}

std::string_view to_string(ChecksumReading r) {
  return r == ChecksumReading::kModulo256 ? "modulo-256" : "end-around-carry";
}

}  // namespace rs4sim::metron
