// RowArchive: store, restore, export and import, once for both engines (row_archive.h).
#include "storage/row_archive.h"

#include "storage/request_check.h"
#include "storage/time_ms.h"

#include <algorithm>
#include <cstdint>
#include <map>

namespace rs4sim::storage {

using boost::outcome_v2::success;

namespace {

// A version of the file that the station already holds: the same bytes, written at the same
// time by the same kind of change from the same device (docs/storage.md "Import").
bool same_version(const VersionInfo& stored, const SnapshotVersion& v, SetId set) {
  return stored.set_id == set && stored.at == v.at && stored.source == v.source &&
         stored.serial_number == v.serial_number;
}

const SnapshotVersion* numbered(const SnapshotStation& in, std::uint32_t number) {
  for (const auto& v : in.versions) {
    if (v.number == number) return &v;
  }
  return nullptr;
}

}  // namespace

Result<VersionInfo> RowArchive::store_rows(const StoreRequest& r) {
  BOOST_OUTCOME_TRY(station, upsert_station(r.station, r.device_type, r.site, r.line));
  BOOST_OUTCOME_TRY(see_serial(station, r.serial_number, r.at, r.at));
  bool inserted = false;
  BOOST_OUTCOME_TRY(set, intern_set(r.blob, r.crc32, r.summary, inserted));
  if (r.skip_identical && !inserted) {
    BOOST_OUTCOME_TRY(current, current_version(station));
    if (current) {
      BOOST_OUTCOME_TRY(info, version_info(*current));
      if (info.set_id == set) return info;
    }
  }
  BOOST_OUTCOME_TRY(clear_pending(station));
  const NewVersion v{set,    r.source, r.at,         r.simulated, r.note, r.serial_number,
                     r.user, r.host,   std::nullopt, false};
  BOOST_OUTCOME_TRY(id, append_version(station, v));
  BOOST_OUTCOME_TRY(make_current(station, id));
  return version_info(id);
}

Result<VersionInfo> RowArchive::store(const StoreRequest& r) {
  return with_context("store " + label(r.station), [&]() -> Result<VersionInfo> {
    BOOST_OUTCOME_TRY(check_request(r));
    return written<VersionInfo>([&] { return store_rows(r); });
  });
}

Result<VersionInfo> RowArchive::restore(VersionId version, Timestamp at, std::string note,
                                        const Author& by) {
  return with_context("restore", [&]() -> Result<VersionInfo> {
    BOOST_OUTCOME_TRY(check_note(note));
    BOOST_OUTCOME_TRY(check_author(by));
    return written<VersionInfo>([&]() -> Result<VersionInfo> {
      BOOST_OUTCOME_TRY(old, version_info(version));
      BOOST_OUTCOME_TRY(station, lock_station(old.station));
      BOOST_OUTCOME_TRY(clear_pending(station));
      // Pending download until the proxy has written it to the device.
      const NewVersion v{old.set_id, VersionSource::kRestore, at, std::nullopt, note, "",
                         by.user,    by.host,                 version, true};
      BOOST_OUTCOME_TRY(id, append_version(station, v));
      BOOST_OUTCOME_TRY(make_current(station, id));
      return version_info(id);
    });
  });
}

Result<std::vector<StationInfo>> RowArchive::stations() {
  return with_context("stations", [&]() -> Result<std::vector<StationInfo>> {
    return read_in_one<std::vector<StationInfo>>([&]() -> Result<std::vector<StationInfo>> {
      BOOST_OUTCOME_TRY(list, list_stations());
      std::vector<StationInfo> out;
      out.reserve(list.size());
      for (auto& entry : list) out.push_back(std::move(entry.second));
      return out;
    });
  });
}

Result<void> RowArchive::log_sync(const SyncLogEntry& entry) {
  return with_context("log sync " + label(entry.station), [&]() -> Result<void> {
    BOOST_OUTCOME_TRY(check_sync(entry));
    return in_write([&]() -> Result<void> {
      BOOST_OUTCOME_TRY(station, upsert_station(entry.station, "", "", ""));
      return insert_sync(station, entry);
    });
  });
}

Result<std::vector<SyncLogEntry>> RowArchive::sync_log(const StationKey& key, std::size_t limit) {
  return with_context("sync log", [&]() -> Result<std::vector<SyncLogEntry>> {
    return read_in_one<std::vector<SyncLogEntry>>([&]() -> Result<std::vector<SyncLogEntry>> {
      BOOST_OUTCOME_TRY(station, find_station(key));
      constexpr std::size_t kAll = static_cast<std::size_t>(INT64_MAX);
      return sync_rows(station, key, static_cast<std::int64_t>(std::min(limit, kAll)));
    });
  });
}

Result<SnapshotStation> RowArchive::export_station(std::int64_t id, StationInfo info) {
  SnapshotStation out;
  out.key = info.key;
  out.device_type = std::move(info.device_type);
  out.site = std::move(info.site);
  out.line = std::move(info.line);
  out.serials = std::move(info.serials);
  BOOST_OUTCOME_TRY(versions, station_versions(id));
  std::map<VersionId, std::uint32_t> numbers;
  for (const auto& v : versions) {
    numbers[v.id] = v.number;
    SnapshotVersion sv{v.number, v.set_id,           v.at,           v.source, v.note,
                       0,        v.pending_download, v.serial_number,
                       v.user,   v.host,             v.simulated};
    if (v.restored_from) sv.restored_from = numbers[*v.restored_from];
    if (info.current == v.id) out.current_version = v.number;
    out.versions.push_back(std::move(sv));
  }
  BOOST_OUTCOME_TRY(log, sync_rows(id, out.key, INT64_MAX));
  out.sync_log = std::move(log);
  return out;
}

Result<Snapshot> RowArchive::export_snapshot(Timestamp exported_at) {
  return with_context("export", [&]() -> Result<Snapshot> {
    return read_in_one<Snapshot>([&]() -> Result<Snapshot> {
      Snapshot snap;
      snap.exported_at = exported_at;
      BOOST_OUTCOME_TRY(sets, all_sets());
      snap.sets = std::move(sets);
      BOOST_OUTCOME_TRY(list, list_stations());
      for (auto& [id, info] : list) {
        BOOST_OUTCOME_TRY(station, export_station(id, std::move(info)));
        snap.stations.push_back(std::move(station));
      }
      return snap;
    });
  });
}

// Whether the file's current version becomes the station's (ImportOptions): the number in the
// file to adopt, or none. Never over a restore still pending download that is newer than it:
// that is what the proxy downloads to the next replacement device.
Result<std::optional<std::uint32_t>> RowArchive::adopt_current(std::int64_t station,
                                                               const SnapshotStation& in,
                                                               const ImportContext& context,
                                                               ImportedStation& out) {
  const SnapshotVersion* wanted = numbered(in, in.current_version);
  if (wanted == nullptr) return std::optional<std::uint32_t>();
  BOOST_OUTCOME_TRY(current, current_version(station));
  if (!current) {
    out.current = ImportCurrent::kMadeCurrent;
    return std::optional<std::uint32_t>(wanted->number);
  }
  BOOST_OUTCOME_TRY(now, version_info(*current));
  if (!context.options.make_current ||
      same_version(now, *wanted, context.set_ids.at(wanted->set_id))) {
    return std::optional<std::uint32_t>();
  }
  if (now.pending_download && now.at >= wanted->at) {
    out.current = ImportCurrent::kKeptPending;
    return std::optional<std::uint32_t>();
  }
  out.current = ImportCurrent::kMadeCurrent;
  return std::optional<std::uint32_t>(wanted->number);
}

Result<std::size_t> RowArchive::import_sync_log(std::int64_t station, const SnapshotStation& in) {
  BOOST_OUTCOME_TRY(logged, sync_rows(station, in.key, INT64_MAX));
  std::vector<bool> matched(logged.size(), false);
  std::size_t added = 0;
  for (auto entry : in.sync_log) {
    entry.station = in.key;
    bool present = false;
    for (std::size_t i = 0; i < logged.size() && !present; ++i) {
      present = !matched[i] && logged[i] == entry;
      if (present) matched[i] = true;
    }
    if (present) continue;
    BOOST_OUTCOME_TRY(insert_sync(station, entry));
    ++added;
  }
  return added;
}

Result<ImportedStation> RowArchive::import_station(const SnapshotStation& in,
                                                   const ImportContext& context) {
  ImportedStation out;
  out.key = in.key;
  BOOST_OUTCOME_TRY(station, upsert_station(in.key, in.device_type, in.site, in.line));  // locks it
  for (const auto& serial : in.serials) {
    BOOST_OUTCOME_TRY(
        see_serial(station, serial.serial_number, serial.first_seen, serial.last_seen));
  }
  BOOST_OUTCOME_TRY(adopt, adopt_current(station, in, context, out));
  if (adopt) {
    BOOST_OUTCOME_TRY(clear_pending(station));
  }
  BOOST_OUTCOME_TRY(stored, station_versions(station));
  std::vector<bool> matched(stored.size(), false);
  std::map<std::uint32_t, VersionId> ids;  // number in the file -> version id here
  for (const auto& v : in.versions) {
    const SetId set = context.set_ids.at(v.set_id);
    const auto it = std::find_if(stored.begin(), stored.end(), [&](const VersionInfo& s) {
      return !matched[static_cast<std::size_t>(&s - stored.data())] && same_version(s, v, set);
    });
    if (it != stored.end()) {
      matched[static_cast<std::size_t>(it - stored.begin())] = true;
      ids[v.number] = it->id;
      ++out.versions_present;
      continue;
    }
    NewVersion nv{set,    v.source, v.at,         v.simulated, v.note, v.serial_number,
                  v.user, v.host,   std::nullopt, v.pending_download && adopt == v.number};
    // (pending only when it becomes current)
    if (v.restored_from != 0) nv.restored_from = ids.at(v.restored_from);
    BOOST_OUTCOME_TRY(id, append_version(station, nv));
    ids[v.number] = id;
    ++out.versions_added;
  }
  if (adopt) {
    BOOST_OUTCOME_TRY(make_current(station, ids.at(*adopt)));
  }
  BOOST_OUTCOME_TRY(added, import_sync_log(station, in));
  out.sync_log_added = added;
  out.sync_log_present = in.sync_log.size() - added;
  BOOST_OUTCOME_TRY(current, current_version(station));
  if (current) {
    BOOST_OUTCOME_TRY(info, version_info(*current));
    out.current_number = info.number;
  }
  return out;
}

Result<ImportSummary> RowArchive::import_snapshot(const Snapshot& snapshot,
                                                  const ImportOptions& options) {
  return with_context("import", [&]() -> Result<ImportSummary> {
    BOOST_OUTCOME_TRY(validate(snapshot));
    return written<ImportSummary>([&]() -> Result<ImportSummary> {
      ImportSummary summary;  // counted again on a retry
      ImportContext context{options, {}};
      auto& set_ids = context.set_ids;
      for (const auto& set : snapshot.sets) {
        bool inserted = false;
        BOOST_OUTCOME_TRY(id, intern_set(set.blob, set.crc32, set.summary, inserted));
        set_ids[set.id] = id;
        if (inserted) ++summary.new_sets;
      }
      for (const auto& station : snapshot.stations) {
        BOOST_OUTCOME_TRY(done, import_station(station, context));
        summary.versions += done.versions_added;
        summary.versions_present += done.versions_present;
        summary.sync_log_entries += done.sync_log_added;
        summary.sync_log_present += done.sync_log_present;
        summary.per_station.push_back(std::move(done));
      }
      summary.stations = summary.per_station.size();
      return summary;
    });
  });
}

}  // namespace rs4sim::storage
