#include "storage/request_check.h"

#include "storage/crc32.h"

#include <cstdio>

namespace rs4sim::storage {

std::string hex32(std::uint32_t v) {
  char text[11];
  std::snprintf(text, sizeof text, "0x%08X", v);
  return text;
}

Result<void> check_address(const StationKey& station) {
  if (station.address > kMaxStationAddress) {
    return archive_error(ArchiveError::kInvalidArgument,
                         "address " + std::to_string(station.address) + " above 126");
  }
  return boost::outcome_v2::success();
}

Result<void> check_request(const StoreRequest& r) {
  BOOST_OUTCOME_TRY(check_address(r.station));
  if (r.blob.empty()) return archive_error(ArchiveError::kInvalidArgument, "empty blob");
  const auto actual = crc32(r.blob);
  if (actual != r.crc32) {
    return archive_error(ArchiveError::kCrcMismatch,
                         "claimed " + hex32(r.crc32) + ", blob has " + hex32(actual));
  }
  return boost::outcome_v2::success();
}

}  // namespace rs4sim::storage
