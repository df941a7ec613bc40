#include "storage/request_check.h"

#include "storage/crc32.h"
#include "storage/parameter_archive.h"  // kMaxProxyStateSize

#include <cstdio>

namespace rs4sim::storage {

std::string hex32(std::uint32_t v) {
  char text[11];
  std::snprintf(text, sizeof text, "0x%08X", v);
  return text;
}

namespace {

// Length of the UTF-8 sequence starting at s[i] (0 when it is not one: a stray continuation
// byte, an overlong form, a surrogate, above U+10FFFF, or cut short).
std::size_t utf8_sequence(std::string_view s, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = b(i);
  if (c < 0x80) return 1;
  std::size_t n = 0;
  unsigned char lo = 0x80, hi = 0xBF;  // the allowed range of the second byte
  if (c >= 0xC2 && c <= 0xDF) {
    n = 2;
  } else if (c >= 0xE0 && c <= 0xEF) {
    n = 3;
    if (c == 0xE0) lo = 0xA0;
    if (c == 0xED) hi = 0x9F;
  } else if (c >= 0xF0 && c <= 0xF4) {
    n = 4;
    if (c == 0xF0) lo = 0x90;
    if (c == 0xF4) hi = 0x8F;
  } else {
    return 0;
  }
  if (i + n > s.size()) return 0;
  if (b(i + 1) < lo || b(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k) {
    if (b(i + k) < 0x80 || b(i + k) > 0xBF) return 0;
  }
  return n;
}

}  // namespace

Result<void> check_text(std::string_view field, std::string_view value, std::size_t max) {
  if (value.size() > max) {
    return archive_error(ArchiveError::kInvalidArgument,
                         std::string(field) + " of " + std::to_string(value.size()) +
                             " bytes (at most " + std::to_string(max) + ")");
  }
  for (std::size_t i = 0; i < value.size();) {
    const std::size_t n = value[i] == '\0' ? 0 : utf8_sequence(value, i);
    if (n == 0) {
      return archive_error(ArchiveError::kInvalidArgument,
                           std::string(field) + ": byte " + std::to_string(i) +
                               (value[i] == '\0' ? " is NUL" : " is not UTF-8"));
    }
    i += n;
  }
  return boost::outcome_v2::success();
}

Result<void> check_station(const StationKey& station) {
  if (station.address > kMaxStationAddress) {
    return archive_error(ArchiveError::kInvalidArgument,
                         "address " + std::to_string(station.address) + " above 126");
  }
  return check_text("bus", station.bus, kMaxNameSize);
}

Result<void> check_note(std::string_view note) { return check_text("note", note, kMaxNoteSize); }

Result<void> check_author(const Author& by) {
  BOOST_OUTCOME_TRY(check_text("user", by.user, kMaxNameSize));
  return check_text("host", by.host, kMaxNameSize);
}

Result<void> check_sync(const SyncLogEntry& entry) {
  BOOST_OUTCOME_TRY(check_station(entry.station));
  return check_text("reason", entry.reason, kMaxNoteSize);
}

Result<void> check_request(const StoreRequest& r) {
  BOOST_OUTCOME_TRY(check_station(r.station));
  BOOST_OUTCOME_TRY(check_text("device type", r.device_type, kMaxNameSize));
  BOOST_OUTCOME_TRY(check_text("serial number", r.serial_number, kMaxNameSize));
  BOOST_OUTCOME_TRY(check_text("summary", r.summary, kMaxSummarySize));
  BOOST_OUTCOME_TRY(check_note(r.note));
  BOOST_OUTCOME_TRY(check_author({r.user, r.host}));
  BOOST_OUTCOME_TRY(check_text("site", r.site, kMaxNameSize));
  BOOST_OUTCOME_TRY(check_text("line", r.line, kMaxNameSize));
  if (r.blob.empty()) return archive_error(ArchiveError::kInvalidArgument, "empty blob");
  const auto actual = crc32(r.blob);
  if (actual != r.crc32) {
    return archive_error(ArchiveError::kCrcMismatch,
                         "claimed " + hex32(r.crc32) + ", blob has " + hex32(actual));
  }
  return boost::outcome_v2::success();
}

}  // namespace rs4sim::storage

namespace rs4sim::storage {

Result<void> check_proxy_state(const StationKey& station, std::span<const std::uint8_t> state) {
  BOOST_OUTCOME_TRY(check_station(station));
  if (state.empty() || state.size() > kMaxProxyStateSize) {
    return archive_error(ArchiveError::kInvalidArgument,
                         "state of " + std::to_string(state.size()) + " bytes (1.." +
                             std::to_string(kMaxProxyStateSize) + " allowed)");
  }
  return boost::outcome_v2::success();
}

}  // namespace rs4sim::storage
