#include "storage/sqlite_schema.h"

#include <array>
#include <string>
#include <string_view>

namespace rs4sim::storage::sqlite {
namespace {

// Migration i brings a file from schema version i to i + 1. Never edit a released step:
// add a new one and raise kSchemaVersion.
constexpr std::array<std::string_view, kSchemaVersion> kMigrations = {
    // 0 -> 1: stations, parameter sets, versions, current set.
    R"sql(
CREATE TABLE stations (
  id          INTEGER PRIMARY KEY,
  bus         TEXT    NOT NULL,
  address     INTEGER NOT NULL CHECK (address BETWEEN 0 AND 126),
  device_type TEXT    NOT NULL,
  UNIQUE (bus, address));
CREATE TABLE station_serials (
  station_id    INTEGER NOT NULL REFERENCES stations(id),
  serial_number TEXT    NOT NULL,
  first_seen_ms INTEGER NOT NULL,
  last_seen_ms  INTEGER NOT NULL,
  PRIMARY KEY (station_id, serial_number));
CREATE TABLE parameter_sets (
  id      INTEGER PRIMARY KEY,
  crc32   INTEGER NOT NULL,
  size    INTEGER NOT NULL,
  blob    BLOB    NOT NULL,
  summary TEXT    NOT NULL);
CREATE INDEX parameter_sets_by_crc ON parameter_sets (crc32, size);
CREATE TABLE versions (
  id            INTEGER PRIMARY KEY,
  station_id    INTEGER NOT NULL REFERENCES stations(id),
  number        INTEGER NOT NULL,
  set_id        INTEGER NOT NULL REFERENCES parameter_sets(id),
  source        INTEGER NOT NULL CHECK (source BETWEEN 1 AND 4),
  stored_at_ms  INTEGER NOT NULL,
  note          TEXT    NOT NULL,
  serial_number TEXT    NOT NULL,
  restored_from INTEGER REFERENCES versions(id),
  UNIQUE (station_id, number));
CREATE INDEX versions_by_set ON versions (set_id);
CREATE TABLE current_versions (
  station_id INTEGER PRIMARY KEY REFERENCES stations(id),
  version_id INTEGER NOT NULL REFERENCES versions(id));
)sql",
    // 1 -> 2: restore pending download (partial index: only pending rows), sync log.
    R"sql(
ALTER TABLE versions ADD COLUMN pending_download INTEGER NOT NULL DEFAULT 0;
CREATE TABLE sync_log (
  id                  INTEGER PRIMARY KEY,
  station_id          INTEGER NOT NULL REFERENCES stations(id),
  at_ms               INTEGER NOT NULL,
  reason              TEXT    NOT NULL,
  direction           INTEGER NOT NULL,
  outcome             INTEGER NOT NULL,
  error_number_fb     INTEGER NOT NULL,
  error_code_sfc      INTEGER NOT NULL,
  error_number_device INTEGER NOT NULL,
  duration_ms         INTEGER NOT NULL);
CREATE INDEX sync_log_by_station ON sync_log (station_id, id);
CREATE INDEX versions_pending ON versions (station_id) WHERE pending_download <> 0;
)sql",
    // 2 -> 3: the proxy's retentive state per bus address (kept apart from stations: a sync
    // can start before the station has a set).
    R"sql(
CREATE TABLE proxy_state (
  bus         TEXT    NOT NULL,
  address     INTEGER NOT NULL CHECK (address BETWEEN 0 AND 126),
  state       BLOB    NOT NULL,
  saved_at_ms INTEGER NOT NULL,
  PRIMARY KEY (bus, address));
)sql",
    // 3 -> 4: what maintenance records: who stored a version and from which computer, the
    // station's site and line above the bus.
    R"sql(
ALTER TABLE versions ADD COLUMN user_name TEXT NOT NULL DEFAULT '';
ALTER TABLE versions ADD COLUMN host_name TEXT NOT NULL DEFAULT '';
ALTER TABLE stations ADD COLUMN site TEXT NOT NULL DEFAULT '';
ALTER TABLE stations ADD COLUMN line TEXT NOT NULL DEFAULT '';
CREATE INDEX stations_by_site ON stations (site, line);
)sql",
    // 4 -> 5: a simulated run's own time beside the wall-clock time a version was written
    // (NULL: a real device's set, and every version written before schema 5).
    R"sql(
ALTER TABLE versions ADD COLUMN simulated_ms INTEGER;
)sql",
};

// Runs a script of several statements (DDL of one migration step), each prepared in turn.
Result<void> run_script(Database& db, std::string_view script, std::string_view what) {
  const char* tail = script.data();
  const char* end = script.data() + script.size();
  while (tail < end) {
    sqlite3_stmt* raw = nullptr;
    const int rc = sqlite3_prepare_v2(db.handle(), tail, static_cast<int>(end - tail), &raw, &tail);
    if (rc != SQLITE_OK) return db.error(rc, what);
    if (raw == nullptr) break;  // only whitespace left
    Statement s(raw);
    BOOST_OUTCOME_TRY(db.run(s, what));
  }
  return boost::outcome_v2::success();
}

Result<void> check_ownership(Database& db, std::int64_t app_id, std::int64_t version) {
  if (app_id == 0 && version == 0) {
    BOOST_OUTCOME_TRY(tables, db.query_int("SELECT count(*) FROM sqlite_schema"));
    if (tables != 0) {
      return archive_error(ArchiveError::kNotAnArchive, "a SQLite database with other tables");
    }
    return boost::outcome_v2::success();
  }
  if (app_id != kApplicationId) {
    return archive_error(ArchiveError::kNotAnArchive, "application_id " + std::to_string(app_id) +
                                                         " is not rs4sim's " +
                                                         std::to_string(kApplicationId));
  }
  if (version > kSchemaVersion) {
    return archive_error(ArchiveError::kNewerSchema, "schema version " + std::to_string(version) +
                                                        ", this rs4sim knows up to " +
                                                        std::to_string(kSchemaVersion));
  }
  return boost::outcome_v2::success();
}

Result<void> migrate(Database& db) {
  BOOST_OUTCOME_TRY(tx, Transaction::begin(db));
  // Read again under the write lock: another process may have migrated meanwhile.
  BOOST_OUTCOME_TRY(version, db.query_int("PRAGMA user_version"));
  for (auto v = version; v < kSchemaVersion; ++v) {
    const auto what = "migrate to schema " + std::to_string(v + 1);
    BOOST_OUTCOME_TRY(run_script(db, kMigrations[static_cast<std::size_t>(v)], what));
  }
  BOOST_OUTCOME_TRY(db.exec("PRAGMA application_id = " + std::to_string(kApplicationId)));
  BOOST_OUTCOME_TRY(db.exec("PRAGMA user_version = " + std::to_string(kSchemaVersion)));
  return tx.commit();
}

}  // namespace

Result<void> prepare_schema(Database& db, bool read_only) {
  BOOST_OUTCOME_TRY(app_id, db.query_int("PRAGMA application_id"));
  BOOST_OUTCOME_TRY(version, db.query_int("PRAGMA user_version"));
  BOOST_OUTCOME_TRY(check_ownership(db, app_id, version));
  if (version == kSchemaVersion) return boost::outcome_v2::success();
  if (read_only) {
    return archive_error(ArchiveError::kReadOnly,
                         "schema version " + std::to_string(version) +
                             " " + std::string(kNeedsMigration) +
                             ", but the archive is opened read-only");
  }
  return migrate(db);
}

}  // namespace rs4sim::storage::sqlite
