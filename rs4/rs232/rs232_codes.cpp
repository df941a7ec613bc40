#include "rs4/rs232/rs232_codes.h"

namespace rs4sim::rs4::rs232 {

std::optional<std::uint16_t> baud_code(std::uint32_t baud) noexcept {
  for (std::size_t i = 0; i < kBaudRates.size(); ++i) {
    if (kBaudRates[i] == baud) return static_cast<std::uint16_t>(i);
  }
  return std::nullopt;
}

std::optional<std::uint32_t> baud_of_code(std::uint16_t code) noexcept {
  if (code >= kBaudRates.size()) return std::nullopt;
  return kBaudRates[code];
}

stream::LineSettings line_8n1(std::uint32_t baud) noexcept {
  return stream::LineSettings{baud, 8, stream::Parity::kNone, 1};
}

}  // namespace rs4sim::rs4::rs232
