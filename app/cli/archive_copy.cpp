// `rs4sim archive copy --from A --to B` (docs/archive-cli.md): the whole history of one archive
// added to another, between any two engines (a SQLite file, a PostgreSQL server), in one
// transaction of the target, then verified against the source.
#include "app/cli/archive_commands.h"

#include <algorithm>
#include <iostream>

namespace rs4sim::app::archive {
namespace {

using rs4::report::JsonWriter;

const storage::ParameterSetRecord* set_of(const storage::Snapshot& s, storage::SetId id) {
  for (const auto& set : s.sets) {
    if (set.id == id) return &set;
  }
  return nullptr;
}

const storage::SnapshotStation* station_of(const storage::Snapshot& s,
                                           const storage::StationKey& key) {
  for (const auto& station : s.stations) {
    if (station.key == key) return &station;
  }
  return nullptr;
}

const storage::SnapshotVersion* numbered(const storage::SnapshotStation& s, std::uint32_t n) {
  for (const auto& v : s.versions) {
    if (v.number == n) return &v;
  }
  return nullptr;
}

// The bytes and every recorded field of a version (its restore reference by the bytes and
// time of the version it names), so that one snapshot's version is found in another's.
bool same_version(const storage::Snapshot& a, const storage::SnapshotStation& as,
                  const storage::SnapshotVersion& av, const storage::Snapshot& b,
                  const storage::SnapshotStation& bs, const storage::SnapshotVersion& bv) {
  const auto* ab = set_of(a, av.set_id);
  const auto* bb = set_of(b, bv.set_id);
  if (ab == nullptr || bb == nullptr || ab->blob != bb->blob || av.at != bv.at ||
      av.source != bv.source || av.note != bv.note || av.serial_number != bv.serial_number ||
      av.user != bv.user || av.host != bv.host) {
    return false;
  }
  const auto* ar = numbered(as, av.restored_from);
  const auto* br = numbered(bs, bv.restored_from);
  if (ar == nullptr || br == nullptr) return ar == br;
  return ar->at == br->at && set_of(a, ar->set_id)->blob == set_of(b, br->set_id)->blob;
}

const storage::SnapshotVersion* find_in(const storage::Snapshot& source,
                                        const storage::SnapshotStation& s,
                                        const storage::SnapshotVersion& v,
                                        const storage::Snapshot& target,
                                        const storage::SnapshotStation& t) {
  for (const auto& tv : t.versions) {
    if (same_version(source, s, v, target, t, tv)) return &tv;
  }
  return nullptr;
}

// What the copy must have given the target (the import recognises what it already holds,
// docs/storage.md "Import"): every station of the source with each of its versions (same
// bytes, time, source, note, serial number, author and restore reference) and sync log
// entries; a station new to the target with the source's current version current. An empty
// string when it holds; else the first difference.
std::string check_copy(const storage::Snapshot& source, const storage::Snapshot& before,
                       const storage::Snapshot& after) {
  for (const auto& s : source.stations) {
    const auto label = station_text(s.key);
    const auto* t = station_of(after, s.key);
    if (t == nullptr) return label + " is missing";
    for (const auto& v : s.versions) {
      if (find_in(source, s, v, after, *t) == nullptr) {
        return label + " version " + std::to_string(v.number) + " is missing";
      }
    }
    const auto* current = numbered(s, s.current_version);
    const auto* now = numbered(*t, t->current_version);
    if (station_of(before, s.key) == nullptr && current != nullptr &&
        (now == nullptr || !same_version(source, s, *current, after, *t, *now))) {
      return label + ": current version";
    }
    for (std::size_t i = 0; i < s.sync_log.size(); ++i) {
      auto expected = s.sync_log[i];
      expected.station = s.key;
      if (std::find(t->sync_log.begin(), t->sync_log.end(), expected) == t->sync_log.end()) {
        return label + ": sync log entry " + std::to_string(i + 1) + " is missing";
      }
    }
  }
  return {};
}

}  // namespace

int run_copy(const ArchiveOptions& o) {
  if (!o.common.archive.empty()) {
    throw UsageError("archive copy: takes --from and --to, not --archive");
  }
  if (o.from.empty() || o.to.empty()) {
    throw UsageError("archive copy: needs --from ARCHIVE and --to ARCHIVE");
  }
  if (o.from == o.to) throw UsageError("archive copy: --from and --to name the same archive");
  CommonOptions from = o.common;
  from.archive = o.from;
  CommonOptions to = o.common;
  to.archive = o.to;
  auto source = open_archive(from, OpenMode::kReadOnly);
  const auto snapshot = unwrap(source->export_snapshot(now()));
  auto target = open_archive(to, OpenMode::kCreateOrWrite);
  const auto before = unwrap(target->export_snapshot(now()));
  const auto summary = unwrap(target->import_snapshot(snapshot));
  const auto after = unwrap(target->export_snapshot(now()));
  const auto problem = check_copy(snapshot, before, after);
  if (!problem.empty()) {
    throw ArchiveCommandError("archive copy: the copy in " + archive_shown(to) +
                              " differs from " + archive_shown(from) + ": " + problem);
  }
  const auto integrity = unwrap(target->check_integrity());
  if (!integrity.ok()) {
    throw ArchiveCommandError("archive copy: " + archive_shown(to) + " fails its integrity check: " +
                              integrity.problems.front());
  }
  if (o.common.json) {
    JsonWriter w(2);
    w.begin_object().field("from", archive_shown(from)).field("to", archive_shown(to));
    w.field("stations", summary.stations).field("versions", summary.versions);
    w.field("versions_present", summary.versions_present).field("new_sets", summary.new_sets);
    w.field("sync_log_entries", summary.sync_log_entries);
    w.field("sync_log_present", summary.sync_log_present).field("verified", true);
    std::cout << w.end_object().str() << "\n";
  } else {
    std::cout << "copied " << summary.stations << " stations, " << version_count(snapshot)
              << " versions (" << summary.versions << " added, " << summary.versions_present
              << " already present; " << summary.new_sets << " new sets), "
              << summary.sync_log_entries << " sync log entries added from "
              << archive_shown(from) << " to " << archive_shown(to) << "; verified\n";
  }
  return 0;
}

}  // namespace rs4sim::app::archive
