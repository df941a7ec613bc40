#pragma once
// A whole archive as values: what export produces and import consumes, independent of
// the backend and of the file format (archive_file.h turns it into protobuf).
// Versions refer to sets by the snapshot-local SetId of `sets`.

#include "storage/errors.h"
#include "storage/types.h"

#include <cstdint>
#include <vector>

namespace rs4sim::storage {

inline constexpr std::uint32_t kExportFormatVersion = 1;

struct SnapshotVersion {
  std::uint32_t number{0};
  SetId set_id{0};
  Timestamp at{};
  VersionSource source{VersionSource::kUpload};
  std::string note;
  std::uint32_t restored_from{0};  // version number, 0 = none
  bool pending_download{false};
  std::string serial_number;
  std::string user;
  std::string host;
  std::optional<std::chrono::milliseconds> simulated;  // VersionInfo::simulated
  bool operator==(const SnapshotVersion&) const = default;
};

struct SnapshotStation {
  StationKey key;
  std::string device_type;
  std::string site;
  std::string line;
  std::vector<SerialSeen> serials;
  std::vector<SnapshotVersion> versions;  // ascending by number
  std::uint32_t current_version{0};       // 0 = none
  std::vector<SyncLogEntry> sync_log;     // oldest first (entry.station ignored)
  bool operator==(const SnapshotStation&) const = default;
};

struct Snapshot {
  std::uint32_t format_version{kExportFormatVersion};
  Timestamp exported_at{};
  std::vector<SnapshotStation> stations;
  std::vector<ParameterSetRecord> sets;
  bool operator==(const Snapshot&) const = default;
};

// What an import does to the current set of a station it finds in the file.
enum class ImportCurrent : std::uint8_t {
  kUnchanged,    // the station's current version stays what it was
  kMadeCurrent,  // the file's current version is now the station's (asked, or it had none)
  kKeptPending,  // asked, but the station's current version is a newer restore pending download
};
// "current unchanged", "made current", "kept: a newer restore is pending download".
[[nodiscard]] const char* to_string(ImportCurrent c) noexcept;

struct ImportOptions {
  // The file's current version of each station becomes the station's current one (never over
  // a newer restore still pending download). Off: the history grows, the present stays; a
  // station without a current version takes the file's in either case.
  bool make_current{false};
};

struct ImportedStation {
  StationKey key;
  std::size_t versions_added{0};
  std::size_t versions_present{0};  // already in the archive: same set, time, source, serial
  std::size_t sync_log_added{0};
  std::size_t sync_log_present{0};  // an identical entry is already logged
  ImportCurrent current{ImportCurrent::kUnchanged};
  std::uint32_t current_number{0};  // the station's current version after the import (0: none)
};

struct ImportSummary {
  std::size_t stations{0};
  std::size_t versions{0};  // added
  std::size_t versions_present{0};
  std::size_t new_sets{0};  // sets not already in the archive
  std::size_t sync_log_entries{0};  // added
  std::size_t sync_log_present{0};
  std::vector<ImportedStation> per_station;  // in the file's order
};

// The set of each station's current version in the file (what an import may make current).
std::vector<const ParameterSetRecord*> current_sets(const Snapshot& snapshot);

// Everything import checks before it writes: format version, each set's CRC-32, unique
// set ids and stations, version numbers strictly increasing, every reference resolves.
Result<void> validate(const Snapshot& snapshot);

}  // namespace rs4sim::storage
