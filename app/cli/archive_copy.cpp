// `rs4sim archive copy --from A --to B` (docs/archive-cli.md): the whole history of one archive
// added to another, between any two engines (a SQLite file, a PostgreSQL server), in one
// transaction of the target, then verified against the source.
#include "app/cli/archive_commands.h"

#include <iostream>
#include <map>

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

// Position (0-based) of version `number` in `versions`, or -1.
long position_of(const std::vector<storage::SnapshotVersion>& versions, std::uint32_t number) {
  for (std::size_t i = 0; i < versions.size(); ++i) {
    if (versions[i].number == number) return static_cast<long>(i);
  }
  return -1;
}

// What the copy must have added to the target: every station of the source, its versions
// appended after the ones the target had (same bytes, time, source, note, serial number,
// pending flag and restore reference), the source's current version current, its sync log
// at the end of the target's. An empty string when it holds; else the first difference.
std::string check_copy(const storage::Snapshot& source, const storage::Snapshot& before,
                       const storage::Snapshot& after) {
  for (const auto& s : source.stations) {
    const auto label = station_text(s.key);
    const auto* t = station_of(after, s.key);
    if (t == nullptr) return label + " is missing";
    const auto* old = station_of(before, s.key);
    const std::size_t base = old == nullptr ? 0 : old->versions.size();
    const std::size_t logs = old == nullptr ? 0 : old->sync_log.size();
    if (t->versions.size() != base + s.versions.size()) return label + ": version count";
    // An empty site or line in the source keeps the target's (as a store without them does).
    if ((!s.site.empty() && t->site != s.site) || (!s.line.empty() && t->line != s.line)) {
      return label + ": site or line";
    }
    for (std::size_t i = 0; i < s.versions.size(); ++i) {
      const auto& sv = s.versions[i];
      const auto& tv = t->versions[base + i];
      const auto what = label + " version " + std::to_string(sv.number);
      const auto* sb = set_of(source, sv.set_id);
      const auto* tb = set_of(after, tv.set_id);
      if (sb == nullptr || tb == nullptr || sb->blob != tb->blob || sb->crc32 != tb->crc32) {
        return what + ": parameter set";
      }
      if (sv.at != tv.at || sv.source != tv.source || sv.note != tv.note ||
          sv.serial_number != tv.serial_number || sv.pending_download != tv.pending_download ||
          sv.user != tv.user || sv.host != tv.host) {
        return what + ": metadata";
      }
      const long sr = sv.restored_from == 0 ? -1 : position_of(s.versions, sv.restored_from);
      const long tr = tv.restored_from == 0 ? -1 : position_of(t->versions, tv.restored_from);
      if ((sr < 0) != (tr < 0) || (sr >= 0 && static_cast<std::size_t>(tr) != base +
                                                  static_cast<std::size_t>(sr))) {
        return what + ": restored_from";
      }
    }
    if (s.current_version != 0) {
      const long sc = position_of(s.versions, s.current_version);
      const long tc = position_of(t->versions, t->current_version);
      if (sc < 0 || tc < 0 || static_cast<std::size_t>(tc) != base + static_cast<std::size_t>(sc)) {
        return label + ": current version";
      }
    }
    if (t->sync_log.size() != logs + s.sync_log.size()) return label + ": sync log length";
    for (std::size_t i = 0; i < s.sync_log.size(); ++i) {
      auto expected = s.sync_log[i];
      auto got = t->sync_log[logs + i];
      expected.station = got.station = {};
      if (!(expected == got)) return label + ": sync log entry " + std::to_string(i + 1);
    }
  }
  return {};
}

std::size_t version_total(const storage::Snapshot& s) {
  std::size_t n = 0;
  for (const auto& station : s.stations) n += station.versions.size();
  return n;
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
    w.field("new_sets", summary.new_sets).field("sync_log_entries", summary.sync_log_entries);
    w.field("verified", true);
    std::cout << w.end_object().str() << "\n";
  } else {
    std::cout << "copied " << summary.stations << " stations, " << version_total(snapshot)
              << " versions (" << summary.new_sets << " new sets), " << summary.sync_log_entries
              << " sync log entries from " << archive_shown(from) << " to " << archive_shown(to)
              << "; verified\n";
  }
  return 0;
}

}  // namespace rs4sim::app::archive
