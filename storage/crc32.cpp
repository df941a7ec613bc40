#include "storage/crc32.h"

#include <zlib.h>

namespace rs4sim::storage {

std::uint32_t crc32(std::span<const std::uint8_t> bytes) noexcept {
  const auto initial = ::crc32_z(0, nullptr, 0);
  return static_cast<std::uint32_t>(::crc32_z(initial, bytes.data(), bytes.size()));
}

}  // namespace rs4sim::storage
