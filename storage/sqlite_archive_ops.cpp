// SqliteArchive: store, read, restore, stations (sqlite_archive.h).
#include "storage/request_check.h"
#include "storage/sqlite_archive.h"
#include "storage/sqlite_rows.h"
#include "storage/time_ms.h"

namespace rs4sim::storage {

using boost::outcome_v2::success;
using sqlite::Transaction;

Result<void> SqliteArchive::clear_pending(std::int64_t station) {
  BOOST_OUTCOME_TRY(s, db_->statement("UPDATE versions SET pending_download = 0 "
                                      "WHERE station_id = ? AND pending_download <> 0"));
  s->bind(1, station);
  return db_->run(*s, "clear pending download");
}

Result<VersionWithSet> SqliteArchive::current(const StationKey& key) {
  return with_context("current", [&]() -> Result<VersionWithSet> {
    auto read = Transaction::begin_read(*db_);  // one snapshot for all reads
    if (!read) return std::move(read).error();
    BOOST_OUTCOME_TRY(station, station_id(key));
    BOOST_OUTCOME_TRY(
        s, db_->statement("SELECT version_id FROM current_versions WHERE station_id = ?"));
    s->bind(1, station);
    const int rc = s->step();
    if (rc == SQLITE_DONE) {
      return archive_error(ArchiveError::kNotFound, label(key) + " has no current set");
    }
    if (rc != SQLITE_ROW) return db_->error(rc, label(key));
    return version_with_set(s->int64(0));
  });
}

Result<std::vector<VersionInfo>> SqliteArchive::history(const StationKey& key) {
  return with_context("history", [&]() -> Result<std::vector<VersionInfo>> {
    return read_in_one<std::vector<VersionInfo>>([&]() -> Result<std::vector<VersionInfo>> {
      BOOST_OUTCOME_TRY(station, station_id(key));
      return station_versions(station);
    });
  });
}

Result<VersionWithSet> SqliteArchive::get(VersionId version) {
  return with_context("get", [&]() -> Result<VersionWithSet> {
    auto read = Transaction::begin_read(*db_);  // one snapshot for all reads
    if (!read) return std::move(read).error();
    return version_with_set(version);
  });
}

Result<void> SqliteArchive::mark_downloaded(VersionId version) {
  return with_context("mark downloaded", [&]() -> Result<void> {
    BOOST_OUTCOME_TRY(tx, Transaction::begin(*db_));
    BOOST_OUTCOME_TRY(version_info(version));
    BOOST_OUTCOME_TRY(s, db_->statement("UPDATE versions SET pending_download = 0 WHERE id = ?"));
    s->bind(1, version);
    BOOST_OUTCOME_TRY(db_->run(*s, "version " + std::to_string(version)));
    return tx.commit();
  });
}

Result<VersionInfo> SqliteArchive::annotate(VersionId version, std::string note) {
  return with_context("note on version " + std::to_string(version), [&]() -> Result<VersionInfo> {
    BOOST_OUTCOME_TRY(check_note(note));
    BOOST_OUTCOME_TRY(tx, Transaction::begin(*db_));
    BOOST_OUTCOME_TRY(version_info(version));
    BOOST_OUTCOME_TRY(s, db_->statement("UPDATE versions SET note = ? WHERE id = ?"));
    s->bind(1, note);
    s->bind(2, version);
    BOOST_OUTCOME_TRY(db_->run(*s, "write note"));
    BOOST_OUTCOME_TRY(info, version_info(version));
    BOOST_OUTCOME_TRY(tx.commit());
    return info;
  });
}

Result<std::vector<VersionInfo>> SqliteArchive::versions_after(VersionId after,
                                                               std::size_t limit) {
  return with_context("versions after " + std::to_string(after),
                      [&]() -> Result<std::vector<VersionInfo>> {
    auto read = Transaction::begin_read(*db_);
    if (!read) return std::move(read).error();
    BOOST_OUTCOME_TRY(s, db_->statement(std::string(kVersionColumns) +
                                        "WHERE v.id > ? ORDER BY v.id LIMIT ?"));
    s->bind(1, after);
    s->bind(2, static_cast<std::int64_t>(std::min<std::size_t>(limit, INT64_MAX)));
    std::vector<VersionInfo> out;
    int rc = SQLITE_ROW;
    while ((rc = s->step()) == SQLITE_ROW) out.push_back(read_version(*s));
    if (rc != SQLITE_DONE) return db_->error(rc, "read versions");
    return out;
  });
}

Result<VersionId> SqliteArchive::newest_version_id() {
  return with_context("newest version", [&]() -> Result<VersionId> {
    return db_->query_int("SELECT coalesce(max(id), 0) FROM versions");
  });
}

Result<std::vector<SerialSeen>> SqliteArchive::serials(std::int64_t station) {
  BOOST_OUTCOME_TRY(
      s, db_->statement("SELECT serial_number, first_seen_ms, last_seen_ms FROM station_serials "
                        "WHERE station_id = ? ORDER BY first_seen_ms, serial_number"));
  s->bind(1, station);
  std::vector<SerialSeen> out;
  int rc = SQLITE_ROW;
  while ((rc = s->step()) == SQLITE_ROW) {
    out.push_back({s->text(0), from_ms(s->int64(1)), from_ms(s->int64(2))});
  }
  if (rc != SQLITE_DONE) return db_->error(rc, "serial numbers");
  return out;
}

Result<std::vector<std::pair<std::int64_t, StationInfo>>> SqliteArchive::list_stations() {
  BOOST_OUTCOME_TRY(
      s, db_->statement(
             "SELECT s.id, s.bus, s.address, s.device_type, c.version_id, s.site, s.line "
             "FROM stations s "
             "LEFT JOIN current_versions c ON c.station_id = s.id ORDER BY s.bus, s.address"));
  std::vector<std::pair<std::int64_t, StationInfo>> out;
  int rc = SQLITE_ROW;
  while ((rc = s->step()) == SQLITE_ROW) {
    StationInfo info;
    info.key = StationKey{s->text(1), static_cast<std::uint8_t>(s->int64(2))};
    info.device_type = s->text(3);
    if (!s->is_null(4)) info.current = s->int64(4);
    info.site = s->text(5);
    info.line = s->text(6);
    out.emplace_back(s->int64(0), std::move(info));
  }
  if (rc != SQLITE_DONE) return db_->error(rc, "list");
  for (auto& [id, info] : out) {
    BOOST_OUTCOME_TRY(seen, serials(id));
    info.serials = std::move(seen);
  }
  return out;
}

}  // namespace rs4sim::storage
