// SqliteArchive: sync log and integrity check (sqlite_archive.h).
#include "storage/crc32.h"
#include "storage/request_check.h"
#include "storage/sqlite_archive.h"
#include "storage/time_ms.h"

namespace rs4sim::storage {

using boost::outcome_v2::success;
using sqlite::Transaction;

Result<void> SqliteArchive::insert_sync(std::int64_t station, const SyncLogEntry& e) {
  BOOST_OUTCOME_TRY(
      s,
      db_->statement(
          "INSERT INTO sync_log (station_id, at_ms, reason, direction, outcome, error_number_fb, "
          "error_code_sfc, error_number_device, duration_ms) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)"));
  s->bind(1, station);
  s->bind(2, to_ms(e.at));
  s->bind(3, e.reason);
  s->bind(4, static_cast<std::int64_t>(e.direction));
  s->bind(5, static_cast<std::int64_t>(e.outcome));
  s->bind(6, std::int64_t{e.error_number_fb});
  s->bind(7, std::int64_t{e.error_code_sfc});
  s->bind(8, std::int64_t{e.error_number_device});
  s->bind(9, static_cast<std::int64_t>(e.duration.count()));
  return db_->run(*s, "insert sync log entry");
}

Result<std::vector<SyncLogEntry>> SqliteArchive::sync_rows(std::int64_t station,
                                                           const StationKey& key,
                                                           std::int64_t limit) {
  BOOST_OUTCOME_TRY(
      s, db_->statement(
             "SELECT at_ms, reason, direction, outcome, error_number_fb, error_code_sfc, "
             "error_number_device, duration_ms FROM (SELECT * FROM sync_log WHERE station_id = ? "
             "ORDER BY id DESC LIMIT ?) ORDER BY id"));
  s->bind(1, station);
  s->bind(2, limit);
  std::vector<SyncLogEntry> out;
  int rc = SQLITE_ROW;
  while ((rc = s->step()) == SQLITE_ROW) {
    SyncLogEntry e;
    e.station = key;
    e.at = from_ms(s->int64(0));
    e.reason = s->text(1);
    e.direction = static_cast<SyncDirection>(s->int64(2));
    e.outcome = static_cast<SyncOutcome>(s->int64(3));
    e.error_number_fb = static_cast<std::uint32_t>(s->int64(4));
    e.error_code_sfc = static_cast<std::uint32_t>(s->int64(5));
    e.error_number_device = static_cast<std::uint32_t>(s->int64(6));
    e.duration = std::chrono::milliseconds{s->int64(7)};
    out.push_back(std::move(e));
  }
  if (rc != SQLITE_DONE) return db_->error(rc, label(key));
  return out;
}

Result<void> SqliteArchive::integrity_pragmas(IntegrityReport& report) {
  {
    BOOST_OUTCOME_TRY(s, db_->statement("PRAGMA integrity_check"));
    int rc = SQLITE_ROW;
    while ((rc = s->step()) == SQLITE_ROW) {
      auto line = s->text(0);
      if (line != "ok") report.problems.push_back("integrity_check: " + line);
    }
    if (rc != SQLITE_DONE) return db_->error(rc, "integrity_check");
  }
  BOOST_OUTCOME_TRY(s, db_->statement("PRAGMA foreign_key_check"));
  int rc = SQLITE_ROW;
  while ((rc = s->step()) == SQLITE_ROW) {
    report.problems.push_back("foreign_key_check: " + s->text(0) + " row " +
                              std::to_string(s->int64(1)) + " has no " + s->text(2) + " row");
  }
  if (rc != SQLITE_DONE) return db_->error(rc, "foreign_key_check");
  return success();
}

Result<void> SqliteArchive::integrity_blobs(IntegrityReport& report) {
  {
    BOOST_OUTCOME_TRY(s, db_->statement("SELECT id, crc32, size, blob FROM parameter_sets"));
    int rc = SQLITE_ROW;
    while ((rc = s->step()) == SQLITE_ROW) {
      const auto blob = s->blob(3);
      const auto id = std::to_string(s->int64(0));
      if (crc32(blob) != static_cast<std::uint32_t>(s->int64(1))) {
        report.problems.push_back("parameter set " + id + ": CRC-32 does not match its blob");
      }
      if (static_cast<std::int64_t>(blob.size()) != s->int64(2)) {
        report.problems.push_back("parameter set " + id + ": size does not match its blob");
      }
    }
    if (rc != SQLITE_DONE) return db_->error(rc, "read parameter sets");
  }
  BOOST_OUTCOME_TRY(
      s, db_->statement(
             "SELECT c.station_id FROM current_versions c JOIN versions v ON v.id = c.version_id "
             "WHERE v.station_id <> c.station_id"));
  int rc = SQLITE_ROW;
  while ((rc = s->step()) == SQLITE_ROW) {
    report.problems.push_back("station " + std::to_string(s->int64(0)) +
                              ": current version belongs to another station");
  }
  if (rc != SQLITE_DONE) return db_->error(rc, "check current versions");
  return success();
}

Result<IntegrityReport> SqliteArchive::check_integrity() {
  return with_context("integrity check", [&]() -> Result<IntegrityReport> {
    auto read = Transaction::begin_read(*db_);  // one snapshot for all reads
    if (!read) return std::move(read).error();
    IntegrityReport report;
    BOOST_OUTCOME_TRY(integrity_pragmas(report));
    BOOST_OUTCOME_TRY(integrity_blobs(report));
    return report;
  });
}

}  // namespace rs4sim::storage
