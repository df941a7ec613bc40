#include "storage/sqlite_archive.h"

#include "storage/crc32.h"
#include "storage/sqlite_rows.h"
#include "storage/sqlite_schema.h"
#include "storage/time_ms.h"

#include <system_error>

namespace rs4sim::storage {

using boost::outcome_v2::success;
using sqlite::Transaction;

namespace {

Result<void> apply_options(sqlite::Database& db, const SqliteOptions& options) {
  sqlite3_busy_timeout(db.handle(), static_cast<int>(options.busy_timeout.count()));
  BOOST_OUTCOME_TRY(db.exec("PRAGMA foreign_keys = ON"));
  BOOST_OUTCOME_TRY(db.exec("PRAGMA cache_size = -" + std::to_string(options.cache_kib)));
  if (options.max_page_count != 0) {
    BOOST_OUTCOME_TRY(db.exec("PRAGMA max_page_count = " + std::to_string(options.max_page_count)));
  }
  if (options.read_only) return success();
  BOOST_OUTCOME_TRY(db.exec("PRAGMA journal_mode = WAL"));
  return db.exec(options.synchronous_full ? "PRAGMA synchronous = FULL"
                                          : "PRAGMA synchronous = NORMAL");
}

}  // namespace

Result<std::unique_ptr<SqliteArchive>> SqliteArchive::open(const std::filesystem::path& path,
                                                           const SqliteOptions& options) {
  return with_context("open " + path.string(), [&]() -> Result<std::unique_ptr<SqliteArchive>> {
    const auto parent = path.parent_path();
    if (!options.read_only && !parent.empty() && path != ":memory:") {
      std::error_code ec;
      std::filesystem::create_directories(parent, ec);
      if (ec) {
        return archive_error(ArchiveError::kIo,
                             "cannot create " + parent.string() + " (" + ec.message() + ")");
      }
    }
    const int flags =
        options.read_only ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE;
    BOOST_OUTCOME_TRY(db, sqlite::Database::open(path.string(), flags));
    BOOST_OUTCOME_TRY(apply_options(*db, options));
    BOOST_OUTCOME_TRY(sqlite::prepare_schema(*db, options.read_only));
    return std::unique_ptr<SqliteArchive>(new SqliteArchive(std::move(db)));
  });
}

Result<std::int64_t> SqliteArchive::station_id(const StationKey& key) {
  BOOST_OUTCOME_TRY(s, db_->statement("SELECT id FROM stations WHERE bus = ? AND address = ?"));
  s->bind(1, key.bus);
  s->bind(2, std::int64_t{key.address});
  const int rc = s->step();
  if (rc == SQLITE_ROW) return s->int64(0);
  if (rc == SQLITE_DONE) {
    auto failure = archive_error(ArchiveError::kUnknownStation, label(key));
    failure.message += " (" + known_stations() + ")";
    return failure;
  }
  return db_->error(rc, label(key));
}

// "the archive has bus demo: 4, 5; bus line2: 7" (or that it has none): what an unknown
// station's error names, so that a wrong --bus is seen at once.
std::string SqliteArchive::known_stations() {
  auto s = db_->statement(
      "SELECT bus, group_concat(address, ', ') FROM "
      "(SELECT bus, address FROM stations ORDER BY bus, address) GROUP BY bus ORDER BY bus");
  if (s.has_error()) return "the archive's stations could not be read";
  const sqlite::StatementUse& rows = s.value();
  std::string text;
  while (rows->step() == SQLITE_ROW) {
    text += (text.empty() ? "the archive has bus " : "; bus ") + rows->text(0) + ": " +
            rows->text(1);
  }
  return text.empty() ? "the archive holds no stations yet" : text;
}

Result<std::int64_t> SqliteArchive::upsert_station(const StationKey& key,
                                                   std::string_view device_type,
                                                   std::string_view site, std::string_view line) {
  BOOST_OUTCOME_TRY(
      s, db_->statement(
             "INSERT INTO stations (bus, address, device_type, site, line) VALUES (?, ?, ?, ?, ?) "
             "ON CONFLICT (bus, address) DO UPDATE SET "
             "device_type = CASE WHEN excluded.device_type <> '' THEN excluded.device_type "
             "ELSE device_type END, "
             "site = CASE WHEN excluded.site <> '' THEN excluded.site ELSE site END, "
             "line = CASE WHEN excluded.line <> '' THEN excluded.line ELSE line END "
             "RETURNING id"));
  s->bind(1, key.bus);
  s->bind(2, std::int64_t{key.address});
  s->bind(3, device_type);
  s->bind(4, site);
  s->bind(5, line);
  const int rc = s->step();
  if (rc != SQLITE_ROW) return db_->error(rc, "write " + label(key));
  return s->int64(0);
}

Result<void> SqliteArchive::see_serial(std::int64_t station, std::string_view serial,
                                       Timestamp first, Timestamp last) {
  if (serial.empty()) return success();
  BOOST_OUTCOME_TRY(s, db_->statement("INSERT INTO station_serials VALUES (?, ?, ?, ?) "
                                      "ON CONFLICT (station_id, serial_number) DO UPDATE SET "
                                      "first_seen_ms = min(first_seen_ms, excluded.first_seen_ms), "
                                      "last_seen_ms = max(last_seen_ms, excluded.last_seen_ms)"));
  s->bind(1, station);
  s->bind(2, serial);
  s->bind(3, to_ms(first));
  s->bind(4, to_ms(last));
  return db_->run(*s, "record serial number " + std::string(serial));
}

Result<SetId> SqliteArchive::intern_set(std::span<const std::uint8_t> blob, std::uint32_t crc,
                                        std::string_view summary, bool& inserted) {
  inserted = false;
  {
    BOOST_OUTCOME_TRY(
        s,
        db_->statement("SELECT id FROM parameter_sets WHERE crc32 = ? AND size = ? AND blob = ?"));
    s->bind(1, std::int64_t{crc});
    s->bind(2, static_cast<std::int64_t>(blob.size()));
    s->bind(3, blob);
    const int rc = s->step();
    if (rc == SQLITE_ROW) return s->int64(0);
    if (rc != SQLITE_DONE) return db_->error(rc, "look up parameter set");
  }
  BOOST_OUTCOME_TRY(
      s, db_->statement(
             "INSERT INTO parameter_sets (crc32, size, blob, summary) VALUES (?, ?, ?, ?)"));
  s->bind(1, std::int64_t{crc});
  s->bind(2, static_cast<std::int64_t>(blob.size()));
  s->bind(3, blob);
  s->bind(4, summary);
  BOOST_OUTCOME_TRY(db_->run(*s, "insert parameter set"));
  inserted = true;
  return sqlite3_last_insert_rowid(db_->handle());
}

Result<VersionId> SqliteArchive::append_version(std::int64_t station, const NewVersion& v) {
  BOOST_OUTCOME_TRY(
      q, db_->statement("SELECT coalesce(max(number), 0) + 1 FROM versions WHERE station_id = ?"));
  q->bind(1, station);
  const int rc = q->step();
  if (rc != SQLITE_ROW) return db_->error(rc, "number new version");
  const std::int64_t number = q->int64(0);
  BOOST_OUTCOME_TRY(
      s, db_->statement(
             "INSERT INTO versions (station_id, number, set_id, source, stored_at_ms, note, "
             "serial_number, restored_from, pending_download, user_name, host_name, "
             "simulated_ms) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)"));
  s->bind(1, station);
  s->bind(2, number);
  s->bind(3, v.set_id);
  s->bind(4, static_cast<std::int64_t>(v.source));
  s->bind(5, to_ms(v.at));
  s->bind(6, v.note);
  s->bind(7, v.serial_number);
  if (v.restored_from) {
    s->bind(8, *v.restored_from);
  } else {
    s->bind_null(8);
  }
  s->bind(9, std::int64_t{v.pending_download ? 1 : 0});
  s->bind(10, v.user);
  s->bind(11, v.host);
  if (v.simulated) {
    s->bind(12, static_cast<std::int64_t>(v.simulated->count()));
  } else {
    s->bind_null(12);
  }
  BOOST_OUTCOME_TRY(db_->run(*s, "insert version"));
  return sqlite3_last_insert_rowid(db_->handle());
}

Result<void> SqliteArchive::make_current(std::int64_t station, VersionId version) {
  BOOST_OUTCOME_TRY(
      s, db_->statement("INSERT INTO current_versions (station_id, version_id) VALUES (?, ?) "
                        "ON CONFLICT (station_id) DO UPDATE SET version_id = excluded.version_id"));
  s->bind(1, station);
  s->bind(2, version);
  return db_->run(*s, "set current version");
}

Result<VersionInfo> SqliteArchive::version_info(VersionId version) {
  BOOST_OUTCOME_TRY(s, db_->statement(std::string(kVersionColumns) + "WHERE v.id = ?"));
  s->bind(1, version);
  const int rc = s->step();
  if (rc == SQLITE_ROW) return read_version(*s);
  const auto what = "version " + std::to_string(version);
  if (rc == SQLITE_DONE) return archive_error(ArchiveError::kUnknownVersion, what);
  return db_->error(rc, what);
}

Result<ParameterSetRecord> SqliteArchive::set_record(SetId set) {
  BOOST_OUTCOME_TRY(s,
                    db_->statement("SELECT crc32, blob, summary FROM parameter_sets WHERE id = ?"));
  s->bind(1, set);
  const int rc = s->step();
  const auto what = "parameter set " + std::to_string(set);
  if (rc == SQLITE_DONE) return archive_error(ArchiveError::kCorruptArchive, what + " missing");
  if (rc != SQLITE_ROW) return db_->error(rc, what);
  return ParameterSetRecord{set, static_cast<std::uint32_t>(s->int64(0)), s->blob(1), s->text(2)};
}

Result<VersionWithSet> SqliteArchive::version_with_set(VersionId version) {
  BOOST_OUTCOME_TRY(info, version_info(version));
  BOOST_OUTCOME_TRY(set, set_record(info.set_id));
  return VersionWithSet{std::move(info), std::move(set)};
}

}  // namespace rs4sim::storage
