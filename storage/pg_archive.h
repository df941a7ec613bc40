#pragma once
// ParameterArchive on a PostgreSQL server through libpq (docs/storage.md "PostgreSQL"): the
// same schema meaning, migrations and error model as SqliteArchive, for a plant where several
// masters and workstations share one archive. Every change is one transaction; a change that
// loses a serialization race or a deadlock is retried; reads are one statement where they can
// (current, history, get), else one REPEATABLE READ READ ONLY transaction. One object per
// connection; not thread-safe (one owner, as the event loop). A connection the server dropped
// is replaced before the next call.

#include "storage/row_archive.h"
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

class PgArchive final : public RowArchive {
 public:
  // Connects with libpq's URI or key=value string (PG* environment variables, sslmode and
  // the password file honoured by libpq), checks and migrates the schema.
  static Result<std::unique_ptr<PgArchive>> open(const std::string& conninfo,
                                                 const PgOptions& options = {});

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

  // The given versions that exist, ascending by id (PgChangeFeed reads what it was notified of).
  Result<std::vector<VersionInfo>> versions_by_id(std::span<const VersionId> ids);

  // The server and database, without the password ("postgresql://user@host:port/db").
  const std::string& display() const noexcept { return c_->display(); }

 private:
  PgArchive(std::unique_ptr<pg::Connection> c, const PgOptions& options)
      : c_(std::move(c)), options_(options) {}

  // Runs `body` in a write transaction, again when it lost a serialization race or a
  // deadlock (the server rolled it back whole).
  template <class T, class F>
  Result<T> write(F&& body);
  template <class T, class F>
  Result<T> read(F&& body);

  Result<void> in_write(const Body& body) override;
  Result<void> in_read(const Body& body) override;
  Result<std::int64_t> lock_station(const StationKey& key) override {
    return station_id(key, true);
  }
  Result<std::int64_t> find_station(const StationKey& key) override {
    return station_id(key, false);
  }
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

  Result<std::int64_t> station_id(const StationKey& key, bool lock);  // kUnknownStation
  std::string known_stations();
  Result<VersionWithSet> version_with_set(VersionId version);

  std::unique_ptr<pg::Connection> c_;
  PgOptions options_;
};

}  // namespace rs4sim::storage
