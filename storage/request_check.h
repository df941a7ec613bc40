#pragma once
// What every backend refuses before it writes (internal to storage/): an address above 126,
// an empty blob, a CRC-32 claim the blob does not bear out.

#include "storage/errors.h"
#include "storage/types.h"

#include <cstdint>
#include <string>

namespace rs4sim::storage {

inline constexpr std::uint8_t kMaxStationAddress = 126;

std::string hex32(std::uint32_t v);  // "0x1A2B3C4D"
Result<void> check_address(const StationKey& station);
Result<void> check_request(const StoreRequest& request);

}  // namespace rs4sim::storage
