#pragma once
// Conversions between Timestamp and the Unix milliseconds the archive stores, and the
// station label used in error messages ("bus1/4").

#include "storage/types.h"

#include <cstdint>
#include <string>

namespace rs4sim::storage {

inline std::int64_t to_ms(Timestamp t) noexcept { return t.time_since_epoch().count(); }
inline Timestamp from_ms(std::int64_t ms) noexcept {
  return Timestamp{std::chrono::milliseconds{ms}};
}
inline std::string label(const StationKey& key) {
  return "station " + key.bus + "/" + std::to_string(key.address);
}

}  // namespace rs4sim::storage
