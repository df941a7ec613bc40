#pragma once
// ParameterArchive on one SQLite file (docs/storage.md): WAL, foreign keys, busy
// timeout, schema version with forward migrations, prepared statements only, every
// change one BEGIN IMMEDIATE transaction, every multi-statement read one read
// transaction. One object per connection; not thread-safe (one owner, as the event loop).

#include "storage/row_archive.h"
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

class SqliteArchive final : public RowArchive {
 public:
  // Opens or creates the archive (and its parent directory); ":memory:" gives a private
  // in-memory archive.
  static Result<std::unique_ptr<SqliteArchive>> open(const std::filesystem::path& path,
                                                     const SqliteOptions& options = {});

  Result<VersionWithSet> current(const StationKey& station) override;
  Result<std::vector<VersionInfo>> history(const StationKey& station) override;
  Result<VersionWithSet> get(VersionId version) override;
  Result<void> mark_downloaded(VersionId version) override;
  Result<VersionInfo> annotate(VersionId version, std::string note) override;
  Result<std::vector<VersionInfo>> versions_after(VersionId after, std::size_t limit) override;
  Result<VersionId> newest_version_id() override;
  Result<void> save_proxy_state(const StationKey& station, std::span<const std::uint8_t> state,
                                Timestamp at) override;
  Result<std::vector<std::uint8_t>> load_proxy_state(const StationKey& station) override;
  Result<IntegrityReport> check_integrity() override;

 private:
  explicit SqliteArchive(std::unique_ptr<sqlite::Database> db) : db_(std::move(db)) {}

  Result<void> in_write(const Body& body) override;
  Result<void> in_read(const Body& body) override;
  Result<std::int64_t> lock_station(const StationKey& key) override { return station_id(key); }
  Result<std::int64_t> find_station(const StationKey& key) override { return station_id(key); }
  Result<std::int64_t> upsert_station(const StationKey& key, std::string_view device_type,
                                      std::string_view site, std::string_view line) override;
  Result<void> see_serial(std::int64_t station, std::string_view serial, Timestamp first,
                          Timestamp last) override;
  Result<SetId> intern_set(std::span<const std::uint8_t> blob, std::uint32_t crc,
                           std::string_view summary, bool& inserted) override;
  Result<VersionId> append_version(std::int64_t station, const NewVersion& v) override;
  Result<void> make_current(std::int64_t station, VersionId version) override;
  Result<void> clear_pending(std::int64_t station) override;
  Result<std::optional<VersionId>> current_version(std::int64_t station) override;
  Result<VersionInfo> version_info(VersionId version) override;
  Result<std::vector<VersionInfo>> station_versions(std::int64_t station) override;
  Result<std::vector<std::pair<std::int64_t, StationInfo>>> list_stations() override;
  Result<std::vector<ParameterSetRecord>> all_sets() override;
  Result<std::vector<SyncLogEntry>> sync_rows(std::int64_t station, const StationKey& key,
                                              std::int64_t limit) override;
  Result<void> insert_sync(std::int64_t station, const SyncLogEntry& entry) override;

  Result<std::int64_t> station_id(const StationKey& key);  // kUnknownStation
  std::string known_stations();
  Result<ParameterSetRecord> set_record(SetId set);
  Result<VersionWithSet> version_with_set(VersionId version);
  Result<std::vector<SerialSeen>> serials(std::int64_t station);
  Result<void> integrity_pragmas(IntegrityReport& report);
  Result<void> integrity_blobs(IntegrityReport& report);

  std::unique_ptr<sqlite::Database> db_;
};

}  // namespace rs4sim::storage
