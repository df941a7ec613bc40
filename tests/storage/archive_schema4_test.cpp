// Schema 4 -> 5 (a simulated run's own time beside each version's wall-clock time): an archive
// the previous rs4sim wrote, on either engine, opens, keeps every row and gains the column
// empty. Both are written here by hand in schema 4, as rs4sim 0.4 created it (its released
// migration steps), with one station, one set ("abc", CRC-32 0x352441C2), two versions (the
// second a restore pending download), a sync log entry and a proxy state.
#include "storage/pg_archive.h"
#include "storage/sqlite_archive.h"
#include "tests/storage/archive_engines.h"
#include "tests/storage/archive_test_support.h"
#include "tests/storage/old_schemas.h"

#include <gtest/gtest.h>

namespace rs4sim::storage {
namespace {

using testing::at_ms;

// Schema 1's tables, then the released steps 1 -> 2 -> 3 -> 4 (sqlite_schema.cpp), and rows.
const std::string kSqliteSchema4 = std::string(testing::kSqliteSchema1Tables) + R"sql(
ALTER TABLE versions ADD COLUMN pending_download INTEGER NOT NULL DEFAULT 0;
CREATE TABLE sync_log (id INTEGER PRIMARY KEY, station_id INTEGER NOT NULL REFERENCES
  stations(id), at_ms INTEGER NOT NULL, reason TEXT NOT NULL, direction INTEGER NOT NULL,
  outcome INTEGER NOT NULL, error_number_fb INTEGER NOT NULL, error_code_sfc INTEGER NOT NULL,
  error_number_device INTEGER NOT NULL, duration_ms INTEGER NOT NULL);
CREATE INDEX sync_log_by_station ON sync_log (station_id, id);
CREATE INDEX versions_pending ON versions (station_id) WHERE pending_download <> 0;
CREATE TABLE proxy_state (bus TEXT NOT NULL, address INTEGER NOT NULL CHECK (address BETWEEN 0
  AND 126), state BLOB NOT NULL, saved_at_ms INTEGER NOT NULL, PRIMARY KEY (bus, address));
ALTER TABLE versions ADD COLUMN user_name TEXT NOT NULL DEFAULT '';
ALTER TABLE versions ADD COLUMN host_name TEXT NOT NULL DEFAULT '';
ALTER TABLE stations ADD COLUMN site TEXT NOT NULL DEFAULT '';
ALTER TABLE stations ADD COLUMN line TEXT NOT NULL DEFAULT '';
CREATE INDEX stations_by_site ON stations (site, line);
INSERT INTO stations VALUES (1, 'plant', 9, 'RS4/PROFIsafe', 'Hamburg', 'L2');
INSERT INTO station_serials VALUES (1, 'S-9', 1000, 2000);
INSERT INTO parameter_sets VALUES (1, 891568578, 3, x'616263', 'abc summary');
INSERT INTO versions VALUES (1, 1, 1, 1, 1, 1000, 'first', 'S-9', NULL, 0, 'jdoe', 'ws-1');
INSERT INTO versions VALUES (2, 1, 2, 1, 4, 3000, 'back', '', 1, 1, 'asmith', 'ws-2');
INSERT INTO current_versions VALUES (1, 2);
INSERT INTO sync_log VALUES (1, 1, 2000, 'power-up', 2, 1, 0, 0, 0, 1500);
INSERT INTO proxy_state VALUES ('plant', 9, x'0102', 2500);
PRAGMA application_id = 1381184577;
PRAGMA user_version = 4;
)sql";

// The same archive in PostgreSQL's schema 4 (pg_schema.cpp's released steps 1 to 4).
constexpr const char* kPgSchema4 = R"sql(
CREATE TABLE rs4sim_archive (application_id bigint NOT NULL, schema_version integer NOT NULL);
CREATE TABLE stations (id bigint GENERATED ALWAYS AS IDENTITY PRIMARY KEY, bus text NOT NULL,
  address smallint NOT NULL CHECK (address BETWEEN 0 AND 126), device_type text NOT NULL,
  site text NOT NULL DEFAULT '', line text NOT NULL DEFAULT '', UNIQUE (bus, address));
CREATE TABLE station_serials (station_id bigint NOT NULL REFERENCES stations(id),
  serial_number text NOT NULL, first_seen timestamptz NOT NULL, last_seen timestamptz NOT NULL,
  PRIMARY KEY (station_id, serial_number));
CREATE TABLE parameter_sets (id bigint GENERATED ALWAYS AS IDENTITY PRIMARY KEY,
  crc32 bigint NOT NULL CHECK (crc32 BETWEEN 0 AND 4294967295), size integer NOT NULL,
  sha256 bytea NOT NULL UNIQUE, blob bytea NOT NULL, summary text NOT NULL);
CREATE TABLE versions (id bigint GENERATED ALWAYS AS IDENTITY PRIMARY KEY,
  station_id bigint NOT NULL REFERENCES stations(id), number integer NOT NULL,
  set_id bigint NOT NULL REFERENCES parameter_sets(id),
  source smallint NOT NULL CHECK (source BETWEEN 1 AND 4), stored_at timestamptz NOT NULL,
  note text NOT NULL, serial_number text NOT NULL, restored_from bigint REFERENCES versions(id),
  pending_download boolean NOT NULL DEFAULT false, user_name text NOT NULL DEFAULT '',
  host_name text NOT NULL DEFAULT '', UNIQUE (station_id, number));
CREATE INDEX versions_by_set ON versions (set_id);
CREATE TABLE current_versions (station_id bigint PRIMARY KEY REFERENCES stations(id),
  version_id bigint NOT NULL REFERENCES versions(id));
CREATE TABLE sync_log (id bigint GENERATED ALWAYS AS IDENTITY PRIMARY KEY,
  station_id bigint NOT NULL REFERENCES stations(id), at timestamptz NOT NULL,
  reason text NOT NULL, direction smallint NOT NULL, outcome smallint NOT NULL,
  error_number_fb bigint NOT NULL, error_code_sfc bigint NOT NULL,
  error_number_device bigint NOT NULL, duration_ms bigint NOT NULL);
CREATE INDEX sync_log_by_station ON sync_log (station_id, id);
CREATE INDEX versions_pending ON versions (station_id) WHERE pending_download;
CREATE TABLE proxy_state (bus text NOT NULL,
  address smallint NOT NULL CHECK (address BETWEEN 0 AND 126), state bytea NOT NULL,
  saved_at timestamptz NOT NULL, PRIMARY KEY (bus, address));
CREATE INDEX stations_by_site ON stations (site, line);
INSERT INTO rs4sim_archive VALUES (1381184577, 4);
INSERT INTO stations (bus, address, device_type, site, line)
  VALUES ('plant', 9, 'RS4/PROFIsafe', 'Hamburg', 'L2');
INSERT INTO station_serials VALUES (1, 'S-9', to_timestamp(1), to_timestamp(2));
INSERT INTO parameter_sets (crc32, size, sha256, blob, summary)
  VALUES (891568578, 3, sha256('\x616263'::bytea), '\x616263'::bytea, 'abc summary');
INSERT INTO versions (station_id, number, set_id, source, stored_at, note, serial_number,
  restored_from, pending_download, user_name, host_name)
  VALUES (1, 1, 1, 1, to_timestamp(1), 'first', 'S-9', NULL, false, 'jdoe', 'ws-1');
INSERT INTO versions (station_id, number, set_id, source, stored_at, note, serial_number,
  restored_from, pending_download, user_name, host_name)
  VALUES (1, 2, 1, 4, to_timestamp(3), 'back', '', 1, true, 'asmith', 'ws-2');
INSERT INTO current_versions VALUES (1, 2);
INSERT INTO sync_log (station_id, at, reason, direction, outcome, error_number_fb,
  error_code_sfc, error_number_device, duration_ms)
  VALUES (1, to_timestamp(2), 'power-up', 2, 1, 0, 0, 0, 1500);
INSERT INTO proxy_state VALUES ('plant', 9, '\x0102'::bytea, to_timestamp(2.5));
)sql";

const StationKey kPlant{"plant", 9};

// Everything schema 4 held, read through the upgraded archive; then a schema-5 write.
void expect_schema4_rows(ParameterArchive& a) {
  const auto history = a.history(kPlant).value();
  ASSERT_EQ(history.size(), 2u);
  EXPECT_EQ(history[0].at, at_ms(1000));
  EXPECT_EQ(history[0].note, "first");
  EXPECT_EQ(history[0].user, "jdoe");
  EXPECT_EQ(history[0].host, "ws-1");
  EXPECT_EQ(history[0].serial_number, "S-9");
  EXPECT_EQ(history[0].crc32, 0x352441C2u);
  EXPECT_FALSE(history[0].simulated);  // written before schema 5
  EXPECT_EQ(history[1].source, VersionSource::kRestore);
  EXPECT_EQ(history[1].restored_from, history[0].id);
  EXPECT_TRUE(history[1].pending_download);
  const auto current = a.current(kPlant).value();
  EXPECT_EQ(current.version.id, history[1].id);
  EXPECT_EQ(current.set.blob, (std::vector<std::uint8_t>{'a', 'b', 'c'}));
  const auto stations = a.stations().value();
  ASSERT_EQ(stations.size(), 1u);
  EXPECT_EQ(stations[0].site, "Hamburg");
  EXPECT_EQ(stations[0].line, "L2");
  ASSERT_EQ(stations[0].serials.size(), 1u);
  EXPECT_EQ(stations[0].serials[0].last_seen, at_ms(2000));
  const auto log = a.sync_log(kPlant, 10).value();
  ASSERT_EQ(log.size(), 1u);
  EXPECT_EQ(log[0].reason, "power-up");
  EXPECT_EQ(log[0].duration, std::chrono::milliseconds{1500});
  EXPECT_EQ(a.load_proxy_state(kPlant).value(), (std::vector<std::uint8_t>{1, 2}));
  EXPECT_TRUE(a.check_integrity().value().ok());
  const auto blob = testing::make_blob(7);
  auto r = testing::request(kPlant, blob, 5000);
  r.simulated = std::chrono::milliseconds{70'000};
  const auto v = a.store(r).value();
  EXPECT_EQ(a.get(v.id).value().version.simulated, std::chrono::milliseconds{70'000});
}

TEST(ArchiveSchema4, ASqliteFileOfTheOldSchemaOpensAndKeepsEveryRow) {
  testing::TempDir dir;
  const auto file = dir.file("v4.sqlite3");
  {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(file.c_str(), &db), SQLITE_OK);
    ASSERT_EQ(sqlite3_exec(db, kSqliteSchema4.c_str(), nullptr, nullptr, nullptr), SQLITE_OK);
    sqlite3_close(db);
  }
  expect_schema4_rows(*SqliteArchive::open(file).value());
}

TEST(ArchiveSchema4, APostgresSchemaOfTheOldSchemaOpensAndKeepsEveryRow) {
  const auto uri = testing::postgres_uri();
  if (!uri) {
    if (testing::postgres_required()) FAIL() << "RS4SIM_REQUIRE_POSTGRES=1 but no server";
    GTEST_SKIP() << "no PostgreSQL server (tests/storage/postgres_server.sh)";
  }
  testing::PgEngine engine(*uri);
  engine.raw().exec("SET search_path = " + engine.schema() + ";\n" + kPgSchema4);
  expect_schema4_rows(*PgArchive::open(engine.location()).value());
  EXPECT_EQ(engine.raw().rows("SELECT schema_version FROM " + engine.schema() +
                              ".rs4sim_archive"),
            (std::vector<std::vector<std::string>>{{"5"}}));
}

}  // namespace
}  // namespace rs4sim::storage
