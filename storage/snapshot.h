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

struct ImportSummary {
  std::size_t stations{0};
  std::size_t versions{0};
  std::size_t new_sets{0};  // sets not already in the archive
  std::size_t sync_log_entries{0};
};

// Everything import checks before it writes: format version, each set's CRC-32, unique
// set ids and stations, version numbers strictly increasing, every reference resolves.
Result<void> validate(const Snapshot& snapshot);

}  // namespace rs4sim::storage
