// PgArchive: sync log, integrity check, export and import (pg_archive.h).
#include "storage/crc32.h"
#include "storage/pg_archive.h"
#include "storage/pg_rows.h"
#include "storage/request_check.h"

#include <algorithm>
#include <map>

namespace rs4sim::storage {

using boost::outcome_v2::success;
using pg::Params;

Result<void> PgArchive::insert_sync(std::int64_t station, const SyncLogEntry& e) {
  Params p;
  p.add(station).add(to_ms(e.at)).add(e.reason).add(static_cast<std::int64_t>(e.direction));
  p.add(static_cast<std::int64_t>(e.outcome)).add(std::int64_t{e.error_number_fb});
  p.add(std::int64_t{e.error_code_sfc}).add(std::int64_t{e.error_number_device});
  p.add(static_cast<std::int64_t>(e.duration.count()));
  BOOST_OUTCOME_TRY(c_->query(
      "INSERT INTO sync_log (station_id, at, reason, direction, outcome, error_number_fb, "
      "error_code_sfc, error_number_device, duration_ms) VALUES ($1::int8, "
      "to_timestamp($2::float8 / 1000), $3::text, $4::int2, $5::int2, $6::int8, $7::int8, "
      "$8::int8, $9::int8)",
      p, "insert sync log entry"));
  return success();
}

Result<void> PgArchive::log_sync(const SyncLogEntry& entry) {
  return with_context("log sync " + label(entry.station), [&]() -> Result<void> {
    BOOST_OUTCOME_TRY(check_sync(entry));
    return write<void>([&]() -> Result<void> {
      BOOST_OUTCOME_TRY(station, upsert_station(entry.station, ""));
      return insert_sync(station, entry);
    });
  });
}

Result<std::vector<SyncLogEntry>> PgArchive::sync_rows(std::int64_t station,
                                                       const StationKey& key,
                                                       std::int64_t limit) {
  Params p;
  p.add(station).add(limit);
  BOOST_OUTCOME_TRY(
      r, c_->query("SELECT (extract(epoch FROM at) * 1000)::int8, reason, direction, outcome, "
                   "error_number_fb, error_code_sfc, error_number_device, duration_ms FROM "
                   "(SELECT * FROM sync_log WHERE station_id = $1::int8 ORDER BY id DESC "
                   "LIMIT $2::int8) newest ORDER BY id",
                   p, label(key)));
  std::vector<SyncLogEntry> out;
  out.reserve(static_cast<std::size_t>(r.count()));
  for (int i = 0; i < r.count(); ++i) {
    SyncLogEntry e;
    e.station = key;
    e.at = from_ms(r.int64(i, 0));
    e.reason = r.text(i, 1);
    e.direction = static_cast<SyncDirection>(r.int64(i, 2));
    e.outcome = static_cast<SyncOutcome>(r.int64(i, 3));
    e.error_number_fb = static_cast<std::uint32_t>(r.int64(i, 4));
    e.error_code_sfc = static_cast<std::uint32_t>(r.int64(i, 5));
    e.error_number_device = static_cast<std::uint32_t>(r.int64(i, 6));
    e.duration = std::chrono::milliseconds{r.int64(i, 7)};
    out.push_back(std::move(e));
  }
  return out;
}

Result<std::vector<SyncLogEntry>> PgArchive::sync_log(const StationKey& key, std::size_t limit) {
  return with_context("sync log", [&]() -> Result<std::vector<SyncLogEntry>> {
    return read<std::vector<SyncLogEntry>>([&]() -> Result<std::vector<SyncLogEntry>> {
      BOOST_OUTCOME_TRY(station, station_id(key, false));
      constexpr std::size_t kAll = static_cast<std::size_t>(INT64_MAX);
      return sync_rows(station, key, static_cast<std::int64_t>(std::min(limit, kAll)));
    });
  });
}

// The server keeps its own structures sound (and refuses a row that breaks a constraint);
// what it cannot know is whether a blob still has the CRC-32 and size the archive claims, and
// that a current version belongs to its station. Blobs are read in pages of kPage rows, so the
// check of a large archive does not hold every set in memory at once.
Result<IntegrityReport> PgArchive::check_integrity() {
  return with_context("integrity check", [&]() -> Result<IntegrityReport> {
    return read<IntegrityReport>([&]() -> Result<IntegrityReport> {
      IntegrityReport report;
      constexpr std::int64_t kPage = 256;
      std::int64_t after = 0;
      for (;;) {
        Params p;
        p.add(after).add(kPage);
        BOOST_OUTCOME_TRY(r, c_->query("SELECT id, crc32, size, blob, sha256 = sha256(blob) "
                                       "FROM parameter_sets WHERE id > $1::int8 ORDER BY id "
                                       "LIMIT $2::int8",
                                       p, "read parameter sets"));
        for (int i = 0; i < r.count(); ++i) {
          const auto blob = r.bytes(i, 3);
          const auto id = std::to_string(r.int64(i, 0));
          if (crc32(blob) != static_cast<std::uint32_t>(r.int64(i, 1))) {
            report.problems.push_back("parameter set " + id + ": CRC-32 does not match its blob");
          }
          if (static_cast<std::int64_t>(blob.size()) != r.int64(i, 2)) {
            report.problems.push_back("parameter set " + id + ": size does not match its blob");
          }
          if (!r.boolean(i, 4)) {
            report.problems.push_back("parameter set " + id + ": SHA-256 does not match its blob");
          }
          after = r.int64(i, 0);
        }
        if (r.count() < kPage) break;
      }
      BOOST_OUTCOME_TRY(
          r, c_->query("SELECT c.station_id FROM current_versions c JOIN versions v "
                       "ON v.id = c.version_id WHERE v.station_id <> c.station_id",
                       "check current versions"));
      for (int i = 0; i < r.count(); ++i) {
        report.problems.push_back("station " + std::to_string(r.int64(i, 0)) +
                                  ": current version belongs to another station");
      }
      return report;
    });
  });
}

Result<SnapshotStation> PgArchive::export_station(std::int64_t id, StationInfo info) {
  SnapshotStation out;
  out.key = info.key;
  out.device_type = std::move(info.device_type);
  out.site = std::move(info.site);
  out.line = std::move(info.line);
  out.serials = std::move(info.serials);
  Params p;
  p.add(id);
  BOOST_OUTCOME_TRY(r, c_->query(version_query("WHERE v.station_id = $1::int8 ORDER BY v.number"),
                                 p, label(out.key)));
  std::map<VersionId, std::uint32_t> numbers;
  for (int i = 0; i < r.count(); ++i) {
    const auto v = read_version(r, i);
    numbers[v.id] = v.number;
    SnapshotVersion sv{v.number, v.set_id,           v.at,           v.source, v.note,
                       0,        v.pending_download, v.serial_number,
                       v.user,   v.host};
    if (v.restored_from) sv.restored_from = numbers[*v.restored_from];
    if (info.current == v.id) out.current_version = v.number;
    out.versions.push_back(std::move(sv));
  }
  BOOST_OUTCOME_TRY(log, sync_rows(id, out.key, INT64_MAX));
  out.sync_log = std::move(log);
  return out;
}

Result<Snapshot> PgArchive::export_snapshot(Timestamp exported_at) {
  return with_context("export", [&]() -> Result<Snapshot> {
    return read<Snapshot>([&]() -> Result<Snapshot> {
      Snapshot snap;
      snap.exported_at = exported_at;
      BOOST_OUTCOME_TRY(
          sets, c_->query("SELECT id, crc32, blob, summary FROM parameter_sets ORDER BY id",
                          "read parameter sets"));
      snap.sets.reserve(static_cast<std::size_t>(sets.count()));
      for (int i = 0; i < sets.count(); ++i) {
        snap.sets.push_back({sets.int64(i, 0), static_cast<std::uint32_t>(sets.int64(i, 1)),
                             sets.bytes(i, 2), sets.text(i, 3)});
      }
      BOOST_OUTCOME_TRY(list, list_stations());
      for (auto& [id, info] : list) {
        BOOST_OUTCOME_TRY(station, export_station(id, std::move(info)));
        snap.stations.push_back(std::move(station));
      }
      return snap;
    });
  });
}

Result<void> PgArchive::import_station(const SnapshotStation& in,
                                       const std::unordered_map<SetId, SetId>& set_ids,
                                       ImportSummary& summary) {
  BOOST_OUTCOME_TRY(station, upsert_station(in.key, in.device_type, in.site, in.line));  // locks the station
  for (const auto& serial : in.serials) {
    BOOST_OUTCOME_TRY(
        see_serial(station, serial.serial_number, serial.first_seen, serial.last_seen));
  }
  // Appended after the station's own versions, as SqliteArchive does.
  std::map<std::uint32_t, VersionId> ids;  // number in the file -> new version id
  for (const auto& v : in.versions) {
    NewVersion nv;
    nv.set_id = set_ids.at(v.set_id);
    nv.source = v.source;
    nv.at = v.at;
    nv.note = v.note;
    nv.serial_number = v.serial_number;
    nv.user = v.user;
    nv.host = v.host;
    nv.pending_download = v.pending_download;
    if (v.restored_from != 0) nv.restored_from = ids.at(v.restored_from);
    BOOST_OUTCOME_TRY(id, append_version(station, nv));
    ids[v.number] = id;
    ++summary.versions;
  }
  if (in.current_version != 0) {
    BOOST_OUTCOME_TRY(make_current(station, ids.at(in.current_version)));
  }
  for (const auto& entry : in.sync_log) {
    BOOST_OUTCOME_TRY(insert_sync(station, entry));
    ++summary.sync_log_entries;
  }
  ++summary.stations;
  return success();
}

Result<ImportSummary> PgArchive::import_snapshot(const Snapshot& snapshot) {
  return with_context("import", [&]() -> Result<ImportSummary> {
    BOOST_OUTCOME_TRY(validate(snapshot));
    return write<ImportSummary>([&]() -> Result<ImportSummary> {
      ImportSummary summary;  // counted again on a retry
      std::unordered_map<SetId, SetId> set_ids;
      for (const auto& set : snapshot.sets) {
        bool inserted = false;
        BOOST_OUTCOME_TRY(id, intern_set(set.blob, set.crc32, set.summary, inserted));
        set_ids[set.id] = id;
        if (inserted) ++summary.new_sets;
      }
      for (const auto& station : snapshot.stations) {
        BOOST_OUTCOME_TRY(import_station(station, set_ids, summary));
      }
      return summary;
    });
  });
}

}  // namespace rs4sim::storage
