// SqliteArchive: export to and import from a Snapshot (sqlite_archive.h).
#include "storage/sqlite_archive.h"
#include "storage/sqlite_rows.h"
#include "storage/time_ms.h"

#include <map>
#include <unordered_map>

namespace rs4sim::storage {

using boost::outcome_v2::success;
using sqlite::Transaction;

Result<SnapshotStation> SqliteArchive::export_station(std::int64_t id, StationInfo info) {
  SnapshotStation out;
  out.key = info.key;
  out.device_type = std::move(info.device_type);
  out.site = std::move(info.site);
  out.line = std::move(info.line);
  out.serials = std::move(info.serials);
  BOOST_OUTCOME_TRY(
      s, db_->statement(std::string(kVersionColumns) + "WHERE v.station_id = ? ORDER BY v.number"));
  s->bind(1, id);
  std::map<VersionId, std::uint32_t> numbers;
  int rc = SQLITE_ROW;
  while ((rc = s->step()) == SQLITE_ROW) {
    const auto v = read_version(*s);
    numbers[v.id] = v.number;
    SnapshotVersion sv{v.number, v.set_id,           v.at,           v.source, v.note,
                       0,        v.pending_download, v.serial_number,
                       v.user,   v.host};
    if (v.restored_from) sv.restored_from = numbers[*v.restored_from];
    if (info.current == v.id) out.current_version = v.number;
    out.versions.push_back(std::move(sv));
  }
  if (rc != SQLITE_DONE) return db_->error(rc, label(out.key));
  BOOST_OUTCOME_TRY(log, sync_rows(id, out.key, INT64_MAX));
  out.sync_log = std::move(log);
  return out;
}

Result<Snapshot> SqliteArchive::export_snapshot(Timestamp exported_at) {
  return with_context("export", [&]() -> Result<Snapshot> {
    auto read = Transaction::begin_read(*db_);  // one snapshot for all reads
    if (!read) return std::move(read).error();
    Snapshot snap;
    snap.exported_at = exported_at;
    {
      BOOST_OUTCOME_TRY(
          s, db_->statement("SELECT id, crc32, blob, summary FROM parameter_sets ORDER BY id"));
      int rc = SQLITE_ROW;
      while ((rc = s->step()) == SQLITE_ROW) {
        snap.sets.push_back(
            {s->int64(0), static_cast<std::uint32_t>(s->int64(1)), s->blob(2), s->text(3)});
      }
      if (rc != SQLITE_DONE) return db_->error(rc, "read parameter sets");
    }
    BOOST_OUTCOME_TRY(list, list_stations());
    for (auto& [id, info] : list) {
      BOOST_OUTCOME_TRY(station, export_station(id, std::move(info)));
      snap.stations.push_back(std::move(station));
    }
    return snap;
  });
}

Result<void> SqliteArchive::import_station(const SnapshotStation& in,
                                           const std::unordered_map<SetId, SetId>& set_ids,
                                           ImportSummary& summary) {
  BOOST_OUTCOME_TRY(station, upsert_station(in.key, in.device_type, in.site, in.line));
  for (const auto& serial : in.serials) {
    BOOST_OUTCOME_TRY(
        see_serial(station, serial.serial_number, serial.first_seen, serial.last_seen));
  }
  // Appended after the station's own versions: number n of the file becomes base + n'.
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

Result<ImportSummary> SqliteArchive::import_snapshot(const Snapshot& snapshot) {
  return with_context("import", [&]() -> Result<ImportSummary> {
    BOOST_OUTCOME_TRY(validate(snapshot));
    BOOST_OUTCOME_TRY(tx, Transaction::begin(*db_));
    ImportSummary summary;
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
    BOOST_OUTCOME_TRY(tx.commit());
    return summary;
  });
}

}  // namespace rs4sim::storage
