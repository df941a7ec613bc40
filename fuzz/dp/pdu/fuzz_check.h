#pragma once
// Shared helpers of the PDU fuzz targets.

#include "dp/fdl/telegram.h"

#include <algorithm>
#include <cstdlib>
#include <span>

namespace rs4sim::dp::pdu::fuzz {

inline void check(bool ok) {
  if (!ok) std::abort();
}

inline bool same(const fdl::DataUnit& du, std::span<const std::uint8_t> bytes) {
  return du.size() == bytes.size() && std::equal(du.begin(), du.end(), bytes.begin());
}

}  // namespace rs4sim::dp::pdu::fuzz
