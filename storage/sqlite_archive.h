#pragma once
// ParameterArchive on one SQLite file (docs/storage.md): WAL, foreign keys, busy
// timeout, schema version with forward migrations, prepared statements only, every
// change one BEGIN IMMEDIATE transaction, every multi-statement read one read
// transaction. One object per connection; not thread-safe (one owner, as the event loop).

#include "storage/parameter_archive.h"
#include "storage/sqlite_db.h"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <unordered_map>
#include <utility>

namespace rs4sim::storage {

struct SqliteOptions {
  bool read_only{false};
  std::chrono::milliseconds busy_timeout{5000};
  // NORMAL (default, SQLite's advice for WAL): a committed change survives a crash of the
  // process (tests/storage/archive_crash_test.cpp), the file stays consistent on power
  // loss but the last commits may be lost; no fsync per commit (>= 2k stores/s).
  // FULL: fsync at every commit, survives power loss (~130 stores/s on the test VM).
  bool synchronous_full{false};
  std::uint32_t max_page_count{0};  // 0 = SQLite's default; a size cap for the file
  // Page cache per connection (SQLite's default is 2 MiB): 16 MiB keeps the current sets
  // of ~1000 stations (3 pages each) and the B-tree interiors in memory.
  std::uint32_t cache_kib{16384};
};

// $XDG_DATA_HOME/rs4sim/archive.sqlite3, else $HOME/.local/share/rs4sim/archive.sqlite3
// (XDG Base Directory Specification). Null or empty arguments count as unset; returns
// "archive.sqlite3" in the working directory when neither is set.
std::filesystem::path default_archive_path(const char* xdg_data_home, const char* home);
// The same, from the process environment.
std::filesystem::path default_archive_path();

class SqliteArchive final : public ParameterArchive {
 public:
  // Opens or creates the archive (and its parent directory); ":memory:" gives a private
  // in-memory archive.
  static Result<std::unique_ptr<SqliteArchive>> open(const std::filesystem::path& path,
                                                     const SqliteOptions& options = {});

  Result<VersionInfo> store(const StoreRequest& request) override;
  Result<VersionWithSet> current(const StationKey& station) override;
  Result<std::vector<VersionInfo>> history(const StationKey& station) override;
  Result<VersionWithSet> get(VersionId version) override;
  using ParameterArchive::restore;
  Result<VersionInfo> restore(VersionId version, Timestamp at, std::string note,
                              const Author& by) override;
  Result<void> mark_downloaded(VersionId version) override;
  Result<VersionInfo> annotate(VersionId version, std::string note) override;
  Result<std::vector<VersionInfo>> versions_after(VersionId after, std::size_t limit) override;
  Result<VersionId> newest_version_id() override;
  Result<std::vector<StationInfo>> stations() override;
  Result<void> log_sync(const SyncLogEntry& entry) override;
  Result<std::vector<SyncLogEntry>> sync_log(const StationKey& station, std::size_t limit) override;
  Result<void> save_proxy_state(const StationKey& station, std::span<const std::uint8_t> state,
                                Timestamp at) override;
  Result<std::vector<std::uint8_t>> load_proxy_state(const StationKey& station) override;
  Result<IntegrityReport> check_integrity() override;
  Result<Snapshot> export_snapshot(Timestamp exported_at) override;
  Result<ImportSummary> import_snapshot(const Snapshot& snapshot) override;

 private:
  struct NewVersion {
    SetId set_id{0};
    VersionSource source{VersionSource::kUpload};
    Timestamp at{};
    std::string_view note;
    std::string_view serial_number;
    std::string_view user;
    std::string_view host;
    std::optional<VersionId> restored_from;
    bool pending_download{false};
    std::optional<std::uint32_t> number;  // default: the station's next number
  };

  explicit SqliteArchive(std::unique_ptr<sqlite::Database> db) : db_(std::move(db)) {}

  Result<std::int64_t> station_id(const StationKey& key);  // kUnknownStation
  std::string known_stations();
  // Creates the station or locks its row; a non-empty device type, site or line replaces the
  // stored one.
  Result<std::int64_t> upsert_station(const StationKey& key, std::string_view device_type,
                                      std::string_view site = {}, std::string_view line = {});
  Result<void> see_serial(std::int64_t station, std::string_view serial, Timestamp first,
                          Timestamp last);
  // The id of the set with exactly these bytes, inserted if new (`inserted` tells).
  Result<SetId> intern_set(std::span<const std::uint8_t> blob, std::uint32_t crc,
                           std::string_view summary, bool& inserted);
  Result<VersionId> append_version(std::int64_t station, const NewVersion& v);
  Result<void> make_current(std::int64_t station, VersionId version);
  Result<void> clear_pending(std::int64_t station);
  Result<std::optional<VersionId>> current_with_set(std::int64_t station, SetId set);
  Result<VersionInfo> version_info(VersionId version);  // kUnknownVersion
  Result<ParameterSetRecord> set_record(SetId set);
  Result<VersionWithSet> version_with_set(VersionId version);
  Result<std::vector<SerialSeen>> serials(std::int64_t station);
  // Every station with its row id, ordered by bus and address (inside a transaction).
  Result<std::vector<std::pair<std::int64_t, StationInfo>>> list_stations();
  Result<std::vector<SyncLogEntry>> sync_rows(std::int64_t station, const StationKey& key,
                                              std::int64_t limit);
  Result<void> integrity_pragmas(IntegrityReport& report);
  Result<void> integrity_blobs(IntegrityReport& report);
  Result<SnapshotStation> export_station(std::int64_t id, StationInfo info);
  Result<void> import_station(const SnapshotStation& station,
                              const std::unordered_map<SetId, SetId>& set_ids,
                              ImportSummary& summary);
  Result<void> insert_sync(std::int64_t station, const SyncLogEntry& entry);

  std::unique_ptr<sqlite::Database> db_;
};

}  // namespace rs4sim::storage
