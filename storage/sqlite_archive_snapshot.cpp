// SqliteArchive: its transactions and the rows RowArchive's store, restore, export and import
// read (sqlite_archive.h).
#include "storage/sqlite_archive.h"
#include "storage/sqlite_rows.h"

namespace rs4sim::storage {

using sqlite::Transaction;

Result<void> SqliteArchive::in_write(const Body& body) {
  BOOST_OUTCOME_TRY(tx, Transaction::begin(*db_));
  BOOST_OUTCOME_TRY(body());
  return tx.commit();
}

Result<void> SqliteArchive::in_read(const Body& body) {
  auto read = Transaction::begin_read(*db_);  // one snapshot for all reads
  if (!read) return std::move(read).error();
  return body();
}

Result<std::optional<VersionId>> SqliteArchive::current_version(std::int64_t station) {
  BOOST_OUTCOME_TRY(s,
                    db_->statement("SELECT version_id FROM current_versions WHERE station_id = ?"));
  s->bind(1, station);
  const int rc = s->step();
  if (rc == SQLITE_ROW) return std::optional<VersionId>(s->int64(0));
  if (rc != SQLITE_DONE) return db_->error(rc, "read current version");
  return std::optional<VersionId>();
}

Result<std::vector<VersionInfo>> SqliteArchive::station_versions(std::int64_t station) {
  BOOST_OUTCOME_TRY(s, db_->statement(std::string(kVersionColumns) +
                                      "WHERE v.station_id = ? ORDER BY v.number"));
  s->bind(1, station);
  std::vector<VersionInfo> out;
  int rc = SQLITE_ROW;
  while ((rc = s->step()) == SQLITE_ROW) out.push_back(read_version(*s));
  if (rc != SQLITE_DONE) return db_->error(rc, "read versions");
  return out;
}

Result<std::vector<ParameterSetRecord>> SqliteArchive::all_sets() {
  BOOST_OUTCOME_TRY(s,
                    db_->statement("SELECT id, crc32, blob, summary FROM parameter_sets ORDER BY id"));
  std::vector<ParameterSetRecord> out;
  int rc = SQLITE_ROW;
  while ((rc = s->step()) == SQLITE_ROW) {
    out.push_back({s->int64(0), static_cast<std::uint32_t>(s->int64(1)), s->blob(2), s->text(3)});
  }
  if (rc != SQLITE_DONE) return db_->error(rc, "read parameter sets");
  return out;
}

}  // namespace rs4sim::storage
