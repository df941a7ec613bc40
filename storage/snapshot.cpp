#include "storage/snapshot.h"

#include "json/message.h"
#include "json/path.h"
#include "storage/crc32.h"
#include "storage/request_check.h"

#include <iterator>
#include <set>
#include <unordered_set>

namespace rs4sim::storage {
namespace {

using boost::outcome_v2::success;

ArchiveFailure corrupt(const std::string& what) {
  return archive_error(ArchiveError::kCorruptImport, what);
}

// A recorded text as check_text() accepts it (both engines store it alike), else a corrupt
// import naming where it is.
Result<void> text_ok(const std::string& where, std::string_view field, std::string_view value,
                     std::size_t max) {
  auto ok = check_text(field, value, max);
  if (!ok) return corrupt(where + ": " + ok.error().message);
  return success();
}

// A check of request_check.h (the writers' own) as a corrupt import naming where it failed.
Result<void> writer_ok(const std::string& where, const Result<void>& ok) {
  if (!ok) return corrupt(where + ": " + ok.error().message);
  return success();
}

// A station as a message names it: "line1/5"; a bus that is no plain name (a control
// character, not UTF-8, long) as a JSON string, cut short.
std::string station_name(const StationKey& key) {
  constexpr std::size_t kShown = 64;
  std::string bus = key.bus;
  if (!check_text("bus", bus, kShown)) bus = json::cut(json::string_literal(bus), kShown);
  return "station " + bus + "/" + std::to_string(key.address);
}

Result<void> validate_sets(const Snapshot& snap, std::unordered_set<SetId>& ids) {
  for (const auto& set : snap.sets) {
    const auto name = "parameter set " + std::to_string(set.id);
    if (set.id <= 0) return corrupt(name + ": id must be >= 1");
    if (!ids.insert(set.id).second) return corrupt(name + ": id used twice");
    if (set.blob.empty()) return corrupt(name + ": empty blob");
    BOOST_OUTCOME_TRY(text_ok(name, "summary", set.summary, kMaxSummarySize));
    if (crc32(set.blob) != set.crc32) {
      return archive_error(ArchiveError::kCrcMismatch, name + ": CRC-32 does not match its blob");
    }
  }
  return success();
}

Result<void> validate_versions(const SnapshotStation& st, const std::string& name,
                               const std::unordered_set<SetId>& set_ids) {
  std::set<std::uint32_t> numbers;
  std::uint32_t last = 0;
  for (const auto& v : st.versions) {
    const auto vname = name + " version " + std::to_string(v.number);
    if (v.number <= last) return corrupt(vname + ": numbers must be >= 1 and increasing");
    last = v.number;
    if (set_ids.count(v.set_id) == 0) return corrupt(vname + ": unknown parameter set");
    const auto source = static_cast<int>(v.source);
    if (source < 1 || source > 4) return corrupt(vname + ": unknown source");
    BOOST_OUTCOME_TRY(text_ok(vname, "note", v.note, kMaxNoteSize));
    BOOST_OUTCOME_TRY(text_ok(vname, "user", v.user, kMaxNameSize));
    BOOST_OUTCOME_TRY(text_ok(vname, "host", v.host, kMaxNameSize));
    BOOST_OUTCOME_TRY(text_ok(vname, "serial number", v.serial_number, kMaxNameSize));
    if (v.restored_from != 0 && numbers.count(v.restored_from) == 0) {
      return corrupt(vname + ": restored from a version that does not precede it");
    }
    numbers.insert(v.number);
  }
  if (st.current_version != 0 && numbers.count(st.current_version) == 0) {
    return corrupt(name + ": current version " + std::to_string(st.current_version) +
                   " not in its versions");
  }
  return success();
}

Result<void> validate_station(const SnapshotStation& st, const std::unordered_set<SetId>& set_ids) {
  const auto name = station_name(st.key);
  BOOST_OUTCOME_TRY(writer_ok(name, check_station(st.key)));
  BOOST_OUTCOME_TRY(text_ok(name, "device type", st.device_type, kMaxNameSize));
  // What the archive itself never holds: a station is made by a store or a sync log entry.
  if (st.versions.empty() && st.sync_log.empty()) {
    return corrupt(name + ": no versions and no sync log (a station without either says "
                          "nothing)");
  }
  BOOST_OUTCOME_TRY(text_ok(name, "site", st.site, kMaxNameSize));
  BOOST_OUTCOME_TRY(text_ok(name, "line", st.line, kMaxNameSize));
  std::set<std::string> serials;
  for (const auto& s : st.serials) {
    BOOST_OUTCOME_TRY(text_ok(name, "serial number", s.serial_number, kMaxNameSize));
    if (s.serial_number.empty() || !serials.insert(s.serial_number).second) {
      return corrupt(name + ": empty or repeated serial number");
    }
    if (s.first_seen > s.last_seen) return corrupt(name + ": serial first seen after last seen");
  }
  BOOST_OUTCOME_TRY(validate_versions(st, name, set_ids));
  for (const auto& e : st.sync_log) {
    const auto direction = static_cast<int>(e.direction);
    const auto outcome = static_cast<int>(e.outcome);
    if (direction < 1 || direction > 4 || outcome < 1 || outcome > 3) {
      return corrupt(name + ": sync log entry with unknown direction or outcome");
    }
    if (e.duration.count() < 0) return corrupt(name + ": negative sync duration");
    BOOST_OUTCOME_TRY(writer_ok(name + " sync log entry", check_sync(e)));
  }
  return success();
}

}  // namespace

Result<void> validate(const Snapshot& snapshot) {
  if (snapshot.format_version != kExportFormatVersion) {
    return corrupt("format version " + std::to_string(snapshot.format_version) +
                   ", this rs4sim reads " + std::to_string(kExportFormatVersion));
  }
  std::unordered_set<SetId> set_ids;
  BOOST_OUTCOME_TRY(validate_sets(snapshot, set_ids));
  std::set<StationKey> keys;
  for (const auto& st : snapshot.stations) {
    if (!keys.insert(st.key).second) {
      return corrupt(station_name(st.key) + " appears twice");
    }
    BOOST_OUTCOME_TRY(validate_station(st, set_ids));
  }
  return success();
}

}  // namespace rs4sim::storage

namespace rs4sim::storage {

std::vector<const ParameterSetRecord*> current_sets(const Snapshot& snapshot) {
  std::vector<const ParameterSetRecord*> out;
  for (const auto& station : snapshot.stations) {
    for (const auto& v : station.versions) {
      if (v.number != station.current_version) continue;
      for (const auto& set : snapshot.sets) {
        if (set.id == v.set_id) out.push_back(&set);
      }
    }
  }
  return out;
}

const char* to_string(ImportCurrent c) noexcept {
  // In the enum's order.
  constexpr const char* kText[] = {"current unchanged", "made current",
                                   "current kept: a newer restore is pending download"};
  const auto i = static_cast<std::size_t>(c);
  return i < std::size(kText) ? kText[i] : "unknown";
}

}  // namespace rs4sim::storage
