#pragma once
// Archive schemas as earlier rs4sim releases wrote them, by hand (the tests that open such
// files must not take them from the code under test).

namespace rs4sim::storage::testing {

// SQLite schema version 1's tables (rs4sim 0.1: no pending_download, no sync_log).
inline constexpr const char* kSqliteSchema1Tables = R"sql(
CREATE TABLE stations (id INTEGER PRIMARY KEY, bus TEXT NOT NULL,
  address INTEGER NOT NULL CHECK (address BETWEEN 0 AND 126), device_type TEXT NOT NULL,
  UNIQUE (bus, address));
CREATE TABLE station_serials (station_id INTEGER NOT NULL REFERENCES stations(id),
  serial_number TEXT NOT NULL, first_seen_ms INTEGER NOT NULL, last_seen_ms INTEGER NOT NULL,
  PRIMARY KEY (station_id, serial_number));
CREATE TABLE parameter_sets (id INTEGER PRIMARY KEY, crc32 INTEGER NOT NULL,
  size INTEGER NOT NULL, blob BLOB NOT NULL, summary TEXT NOT NULL);
CREATE INDEX parameter_sets_by_crc ON parameter_sets (crc32, size);
CREATE TABLE versions (id INTEGER PRIMARY KEY,
  station_id INTEGER NOT NULL REFERENCES stations(id), number INTEGER NOT NULL,
  set_id INTEGER NOT NULL REFERENCES parameter_sets(id),
  source INTEGER NOT NULL CHECK (source BETWEEN 1 AND 4), stored_at_ms INTEGER NOT NULL,
  note TEXT NOT NULL, serial_number TEXT NOT NULL,
  restored_from INTEGER REFERENCES versions(id), UNIQUE (station_id, number));
CREATE INDEX versions_by_set ON versions (set_id);
CREATE TABLE current_versions (station_id INTEGER PRIMARY KEY REFERENCES stations(id),
  version_id INTEGER NOT NULL REFERENCES versions(id));
)sql";

}  // namespace rs4sim::storage::testing
