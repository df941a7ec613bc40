#pragma once
// The parameter archive as the proxy, the CLI and the RPC see it. Narrow on purpose:
// value types in and out, no SQL, no handles, so a second backend (PostgreSQL) can
// implement it without touching a caller. SqliteArchive (sqlite_archive.h) is the
// embedded default.
//
// Contract for every backend:
//   - each call that changes the archive is one transaction: it happens completely or
//     not at all; on any error the archive is unchanged;
//   - the archive reads no clock: every instant comes from the caller;
//   - a parameter set is stored once per distinct byte string (deduplicated); its
//     CRC-32 is computed by the archive and must equal the caller's claim.

#include "storage/errors.h"
#include "storage/snapshot.h"
#include "storage/types.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rs4sim::storage {

inline constexpr std::size_t kMaxProxyStateSize = 256;

class ParameterArchive {
 public:
  virtual ~ParameterArchive() = default;

  // New version of the station (created on first use), becomes its current set.
  virtual Result<VersionInfo> store(const StoreRequest& request) = 0;
  virtual Result<VersionWithSet> current(const StationKey& station) = 0;
  // All versions of the station, ascending by number.
  virtual Result<std::vector<VersionInfo>> history(const StationKey& station) = 0;
  virtual Result<VersionWithSet> get(VersionId version) = 0;
  // New version (source kRestore) with the same set as `version`; becomes current and is
  // pending download until mark_downloaded().
  virtual Result<VersionInfo> restore(VersionId version, Timestamp at, std::string note,
                                      const Author& by) = 0;
  Result<VersionInfo> restore(VersionId version, Timestamp at, std::string note) {
    return restore(version, at, std::move(note), Author{});
  }
  virtual Result<void> mark_downloaded(VersionId version) = 0;
  // Replaces the version's comment (`rs4sim archive note`); the set and its history stay.
  virtual Result<VersionInfo> annotate(VersionId version, std::string note) = 0;
  // The change feed: versions with an id above `after`, ascending by id, at most `limit`.
  // Ids grow with every version stored; on SQLite they are committed in that order, so a
  // reader that polls with the last id it saw misses none. PostgreSQL commits concurrent
  // writers out of id order: its feed (change_feed.h) adds the notifications.
  virtual Result<std::vector<VersionInfo>> versions_after(VersionId after, std::size_t limit) = 0;
  // The highest version id stored (0: none): where a feed that wants only new versions starts.
  virtual Result<VersionId> newest_version_id() = 0;
  virtual Result<std::vector<StationInfo>> stations() = 0;

  virtual Result<void> log_sync(const SyncLogEntry& entry) = 0;
  // The station's newest `limit` entries, oldest first.
  virtual Result<std::vector<SyncLogEntry>> sync_log(const StationKey& station,
                                                     std::size_t limit) = 0;

  // The proxy's retentive state of the station at `station` (the Proxy-FB keeps 34 retentive
  // bytes, [RS4 manual §6.4]): an opaque record of at most kMaxProxyStateSize bytes, replaced
  // on every save, so a restarted proxy resumes or fails safely. Not part of an export.
  virtual Result<void> save_proxy_state(const StationKey& station,
                                        std::span<const std::uint8_t> state, Timestamp at) = 0;
  // kNotFound when nothing was saved for that address.
  virtual Result<std::vector<std::uint8_t>> load_proxy_state(const StationKey& station) = 0;

  // Structural checks of the backend plus every stored blob's CRC-32 re-computed.
  virtual Result<IntegrityReport> check_integrity() = 0;

  virtual Result<Snapshot> export_snapshot(Timestamp exported_at) = 0;
  // validate()s the snapshot, then adds it in one transaction: stations are matched by
  // bus/address (created if new); a version already there (same set, time, source and serial
  // number) or an identical sync log entry is recognised and not added again; the others are
  // appended after the existing versions (renumbered, everything else kept). The current set
  // changes only as ImportOptions says; the summary says what happened per station.
  virtual Result<ImportSummary> import_snapshot(const Snapshot& snapshot,
                                                const ImportOptions& options) = 0;
  Result<ImportSummary> import_snapshot(const Snapshot& snapshot) {
    return import_snapshot(snapshot, ImportOptions{});
  }

 protected:
  ParameterArchive() = default;
  ParameterArchive(const ParameterArchive&) = default;
  ParameterArchive& operator=(const ParameterArchive&) = default;
};

}  // namespace rs4sim::storage
