#pragma once
// ParameterArchive on a PostgreSQL server through libpq (docs/storage.md "PostgreSQL"): the
// same schema meaning, migrations and error model as SqliteArchive, for a plant where several
// masters and workstations share one archive. Every change is one transaction; a change that
// loses a serialization race or a deadlock is retried; reads are one statement where they can
// (current, history, get), else one REPEATABLE READ READ ONLY transaction. One object per
// connection; not thread-safe (one owner, as the event loop). A connection the server dropped
// is replaced before the next call.

#include "storage/parameter_archive.h"
#include "storage/pg_db.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>

namespace rs4sim::storage {

// The channel of the change feed's notifications; the payload is "<schema> <version id>"
// (one database can hold several archives, one per schema). pg_archive.cpp's version insert
// spells the same name.
inline constexpr std::string_view kVersionChannel = "rs4sim_versions";

struct PgOptions {
  // Every transaction READ ONLY (the server refuses a write); the schema must be current.
  bool read_only{false};
  // How often a change that lost a serialization race or a deadlock runs again.
  int max_attempts{5};
};

class PgArchive final : public ParameterArchive {
 public:
  // Connects with libpq's URI or key=value string (PG* environment variables, sslmode and
  // the password file honoured by libpq), checks and migrates the schema.
  static Result<std::unique_ptr<PgArchive>> open(const std::string& conninfo,
                                                 const PgOptions& options = {});

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

  // The given versions that exist, ascending by id (PgChangeFeed reads what it was notified of).
  Result<std::vector<VersionInfo>> versions_by_id(std::span<const VersionId> ids);

  // The server and database, without the password ("postgresql://user@host:port/db").
  const std::string& display() const noexcept { return c_->display(); }

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
  };

  PgArchive(std::unique_ptr<pg::Connection> c, const PgOptions& options)
      : c_(std::move(c)), options_(options) {}

  // Runs `body` in a write transaction, again when it lost a serialization race or a
  // deadlock (the server rolled it back whole).
  template <class T, class F>
  Result<T> write(F&& body);
  template <class T, class F>
  Result<T> read(F&& body);

  Result<std::int64_t> station_id(const StationKey& key, bool lock);  // kUnknownStation
  std::string known_stations();
  // Creates the station or locks its row; a non-empty device type, site or line replaces the
  // stored one.
  Result<std::int64_t> upsert_station(const StationKey& key, std::string_view device_type,
                                      std::string_view site = {}, std::string_view line = {});
  Result<void> see_serial(std::int64_t station, std::string_view serial, Timestamp first,
                          Timestamp last);
  Result<SetId> intern_set(std::span<const std::uint8_t> blob, std::uint32_t crc,
                           std::string_view summary, bool& inserted);
  Result<VersionId> append_version(std::int64_t station, const NewVersion& v);
  Result<void> make_current(std::int64_t station, VersionId version);
  Result<void> clear_pending(std::int64_t station);
  Result<std::optional<VersionId>> current_with_set(std::int64_t station, SetId set);
  Result<VersionInfo> version_info(VersionId version);  // kUnknownVersion
  Result<VersionWithSet> version_with_set(VersionId version);
  Result<std::vector<std::pair<std::int64_t, StationInfo>>> list_stations();
  Result<std::vector<SyncLogEntry>> sync_rows(std::int64_t station, const StationKey& key,
                                              std::int64_t limit);
  Result<void> insert_sync(std::int64_t station, const SyncLogEntry& entry);
  Result<SnapshotStation> export_station(std::int64_t id, StationInfo info);
  Result<void> import_station(const SnapshotStation& station,
                              const std::unordered_map<SetId, SetId>& set_ids,
                              ImportSummary& summary);

  std::unique_ptr<pg::Connection> c_;
  PgOptions options_;
};

}  // namespace rs4sim::storage
