#pragma once
// What every backend refuses before it writes: an address above 126, an empty blob, a CRC-32
// claim the blob does not bear out, a recorded text it would not store alike (every text a
// write takes: bus, device type, serial number, summary, note, user, host, site, line, a sync
// log entry's reason). The import checks a file's texts with the same functions. The CLI checks
// its --user/--site/--line/--note with the same check_text() before it opens an archive.

#include "storage/errors.h"
#include "storage/types.h"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace rs4sim::storage {

inline constexpr std::uint8_t kMaxStationAddress = 126;

std::string hex32(std::uint32_t v);  // "0x1A2B3C4D"
// The address (0..126) and the bus name (a name, check_text()).
Result<void> check_station(const StationKey& station);
Result<void> check_request(const StoreRequest& request);
// A sync log entry's station and reason (a note's limit).
Result<void> check_sync(const SyncLogEntry& entry);
// A proxy state's station, and its size (1..kMaxProxyStateSize bytes).
Result<void> check_proxy_state(const StationKey& station, std::span<const std::uint8_t> state);

// The recorded texts (docs/storage.md "What maintenance records"): UTF-8 without NUL (what
// both engines store alike), a comment up to kMaxNoteSize bytes, a user, host, site or line
// up to kMaxNameSize.
inline constexpr std::size_t kMaxNoteSize = 4096;
inline constexpr std::size_t kMaxNameSize = 256;
// A set's decoded summary (the writer's text or JSON, a few kB for an RS4 set).
inline constexpr std::size_t kMaxSummarySize = 1U << 20;
Result<void> check_text(std::string_view field, std::string_view value, std::size_t max);
Result<void> check_note(std::string_view note);
Result<void> check_author(const Author& by);  // its user and host

}  // namespace rs4sim::storage
