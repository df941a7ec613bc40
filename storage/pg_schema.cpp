#include "storage/pg_schema.h"

#include "storage/schema_version.h"

#include <array>
#include <string>
#include <string_view>

namespace rs4sim::storage::pg {
namespace {

using boost::outcome_v2::success;

// Migration i brings a schema from version i to i + 1, with the meaning of the SQLite step of
// the same number (sqlite_schema.cpp). Never edit a released step: add one and raise
// kArchiveSchemaVersion on both engines. Times are timestamptz (psql shows dates); blobs are
// deduplicated by their SHA-256 under a unique index, so two writers storing the same new
// set at once keep one row.
constexpr std::array<std::string_view, kArchiveSchemaVersion> kMigrations = {
    // 0 -> 1: the owner mark, stations, parameter sets, versions, current set.
    R"sql(
CREATE TABLE rs4sim_archive (
  application_id bigint NOT NULL,
  schema_version integer NOT NULL);
CREATE TABLE stations (
  id          bigint GENERATED ALWAYS AS IDENTITY PRIMARY KEY,
  bus         text     NOT NULL,
  address     smallint NOT NULL CHECK (address BETWEEN 0 AND 126),
  device_type text     NOT NULL,
  UNIQUE (bus, address));
CREATE TABLE station_serials (
  station_id    bigint      NOT NULL REFERENCES stations(id),
  serial_number text        NOT NULL,
  first_seen    timestamptz NOT NULL,
  last_seen     timestamptz NOT NULL,
  PRIMARY KEY (station_id, serial_number));
CREATE TABLE parameter_sets (
  id      bigint GENERATED ALWAYS AS IDENTITY PRIMARY KEY,
  crc32   bigint  NOT NULL CHECK (crc32 BETWEEN 0 AND 4294967295),
  size    integer NOT NULL,
  sha256  bytea   NOT NULL UNIQUE,
  blob    bytea   NOT NULL,
  summary text    NOT NULL);
CREATE TABLE versions (
  id            bigint GENERATED ALWAYS AS IDENTITY PRIMARY KEY,
  station_id    bigint      NOT NULL REFERENCES stations(id),
  number        integer     NOT NULL,
  set_id        bigint      NOT NULL REFERENCES parameter_sets(id),
  source        smallint    NOT NULL CHECK (source BETWEEN 1 AND 4),
  stored_at     timestamptz NOT NULL,
  note          text        NOT NULL,
  serial_number text        NOT NULL,
  restored_from bigint      REFERENCES versions(id),
  UNIQUE (station_id, number));
CREATE INDEX versions_by_set ON versions (set_id);
CREATE TABLE current_versions (
  station_id bigint PRIMARY KEY REFERENCES stations(id),
  version_id bigint NOT NULL REFERENCES versions(id));
)sql",
    // 1 -> 2: restore pending download (partial index: only pending rows), sync log.
    R"sql(
ALTER TABLE versions ADD COLUMN pending_download boolean NOT NULL DEFAULT false;
CREATE TABLE sync_log (
  id                  bigint GENERATED ALWAYS AS IDENTITY PRIMARY KEY,
  station_id          bigint      NOT NULL REFERENCES stations(id),
  at                  timestamptz NOT NULL,
  reason              text        NOT NULL,
  direction           smallint    NOT NULL,
  outcome             smallint    NOT NULL,
  error_number_fb     bigint      NOT NULL,
  error_code_sfc      bigint      NOT NULL,
  error_number_device bigint      NOT NULL,
  duration_ms         bigint      NOT NULL);
CREATE INDEX sync_log_by_station ON sync_log (station_id, id);
CREATE INDEX versions_pending ON versions (station_id) WHERE pending_download;
)sql",
    // 2 -> 3: the proxy's retentive state per bus address.
    R"sql(
CREATE TABLE proxy_state (
  bus      text        NOT NULL,
  address  smallint    NOT NULL CHECK (address BETWEEN 0 AND 126),
  state    bytea       NOT NULL,
  saved_at timestamptz NOT NULL,
  PRIMARY KEY (bus, address));
)sql",
    // 3 -> 4: who stored a version and from which computer, the station's site and line.
    R"sql(
ALTER TABLE versions ADD COLUMN user_name text NOT NULL DEFAULT '',
                     ADD COLUMN host_name text NOT NULL DEFAULT '';
ALTER TABLE stations ADD COLUMN site text NOT NULL DEFAULT '',
                     ADD COLUMN line text NOT NULL DEFAULT '';
CREATE INDEX stations_by_site ON stations (site, line);
)sql",
    // 4 -> 5: a simulated run's own time beside the time a version was written.
    R"sql(
ALTER TABLE versions ADD COLUMN simulated_ms bigint;
)sql",
};

struct SchemaState {
  std::string schema;  // the current schema's name
  std::int64_t version{0};
};

// What the current schema holds: version 0 when it is empty; kNotAnArchive when it holds
// other tables, or a mark that is not ours; kNewerSchema above our version.
Result<SchemaState> read_state(Connection& c) {
  BOOST_OUTCOME_TRY(where, c.query("SELECT current_schema()::text, "
                                   "to_regclass('rs4sim_archive') IS NOT NULL, "
                                   "(SELECT count(*) FROM pg_catalog.pg_tables "
                                   "WHERE schemaname = current_schema())",
                                   "read the schema"));
  if (where.is_null(0, 0)) {
    return archive_error(ArchiveError::kNotAnArchive,
                         "the search_path names no schema that exists in this database");
  }
  SchemaState state{where.text(0, 0), 0};
  if (!where.boolean(0, 1)) {
    if (where.int64(0, 2) != 0) {
      return archive_error(ArchiveError::kNotAnArchive,
                           "schema " + state.schema + " holds " +
                               std::to_string(where.int64(0, 2)) +
                               " tables of something else (no rs4sim_archive table)");
    }
    return state;
  }
  BOOST_OUTCOME_TRY(mark, c.query("SELECT application_id, schema_version::int8, "
                                  "(SELECT count(*) FROM rs4sim_archive) FROM rs4sim_archive",
                                  "read the archive mark"));
  if (mark.count() != 1 || mark.int64(0, 2) != 1) {
    return archive_error(ArchiveError::kNotAnArchive,
                         "schema " + state.schema + ": its rs4sim_archive table holds " +
                             std::to_string(mark.count()) + " rows, not one");
  }
  if (mark.int64(0, 0) != kArchiveApplicationId) {
    return archive_error(ArchiveError::kNotAnArchive,
                         "schema " + state.schema + ": application_id " +
                             std::to_string(mark.int64(0, 0)) + " is not rs4sim's " +
                             std::to_string(kArchiveApplicationId));
  }
  state.version = mark.int64(0, 1);
  if (state.version > kArchiveSchemaVersion) {
    return archive_error(ArchiveError::kNewerSchema,
                         "schema version " + std::to_string(state.version) +
                             ", this rs4sim knows up to " + std::to_string(kArchiveSchemaVersion));
  }
  return state;
}

Result<void> migrate(Connection& c) {
  BOOST_OUTCOME_TRY(tx, Transaction::begin(c, Transaction::Kind::kWrite));
  // One migrator at a time per database; read again under the lock: another process may
  // have migrated meanwhile (READ COMMITTED: the statement after the lock sees its commit).
  Params lock;
  lock.add(kArchiveApplicationId);
  BOOST_OUTCOME_TRY(c.query("SELECT pg_advisory_xact_lock($1::int8)", lock, "lock the schema"));
  BOOST_OUTCOME_TRY(state, read_state(c));
  for (auto v = state.version; v < kArchiveSchemaVersion; ++v) {
    BOOST_OUTCOME_TRY(c.exec(kMigrations[static_cast<std::size_t>(v)],
                             "migrate to schema " + std::to_string(v + 1)));
  }
  Params mark;
  mark.add(kArchiveApplicationId).add(kArchiveSchemaVersion);
  BOOST_OUTCOME_TRY(c.query("DELETE FROM rs4sim_archive", "write the archive mark"));
  BOOST_OUTCOME_TRY(c.query("INSERT INTO rs4sim_archive VALUES ($1::int8, $2::int4)", mark,
                            "write the archive mark"));
  return tx.commit();
}

}  // namespace

Result<void> prepare_schema(Connection& c, bool read_only) {
  BOOST_OUTCOME_TRY(state, read_state(c));
  if (state.version == kArchiveSchemaVersion) return success();
  if (read_only) {
    if (state.version == 0) {
      return archive_error(ArchiveError::kNotAnArchive,
                           "schema " + state.schema + " " + std::string(kNoArchiveYet));
    }
    return archive_error(ArchiveError::kReadOnly,
                         "schema version " + std::to_string(state.version) +
                             " " + std::string(kNeedsMigration) +
                             ", but the archive is opened read-only");
  }
  return migrate(c);
}

}  // namespace rs4sim::storage::pg
