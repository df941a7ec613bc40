// `rs4sim archive show` and `rs4sim archive diff` (docs/archive-cli.md): decoded
// parameters, the field-level difference, and the SVG pictures (rs4/report).
#include "app/cli/archive_commands.h"
#include "rs4/report/field_svg.h"
#include "rs4/report/parameter_diff.h"
#include "rs4/report/parameter_summary.h"

#include <cstdio>
#include <cstdlib>
#include <iostream>

namespace rs4sim::app::archive {
namespace {

using rs4::report::JsonWriter;

void row(const std::string& name, const std::string& value) {
  char b[32];
  std::snprintf(b, sizeof b, "  %-20s ", name.c_str());
  std::cout << b << value << "\n";
}

std::string describe(const storage::VersionInfo& v) {
  return "version " + std::to_string(v.id) + " (" + station_text(v.station) + " #" +
         std::to_string(v.number) + ", " + crc_hex(v.crc32) + ")";
}

void print_version(const storage::VersionWithSet& v, bool is_current) {
  const auto& info = v.version;
  std::cout << "version " << info.id << " of station " << station_text(info.station) << " (number "
            << info.number << (is_current ? ", current" : "") << ")\n";
  row("stored", table_time(info.at) + " UTC, " + source_name(info.source) +
                    (info.serial_number.empty() ? "" : ", serial number " + info.serial_number));
  row("set", "id " + std::to_string(v.set.id) + ", " + std::to_string(v.set.blob.size()) +
                 " bytes, CRC-32 " + crc_hex(v.set.crc32));
  if (!info.note.empty()) row("note", info.note);
  if (const auto by = author_text(info); !by.empty()) row("by", by);
  if (info.restored_from) row("restores version", std::to_string(*info.restored_from));
  row("pending download", info.pending_download ? "yes" : "no");
}

storage::VersionWithSet select_shown(storage::ParameterArchive& a, const ArchiveOptions& o) {
  if (o.ids.size() > 1) throw UsageError("archive show: one version id at most");
  if (o.ids.size() == 1) {
    if (o.common.address)
      throw UsageError("archive show: give a version id or --address, not both");
    return unwrap(a.get(o.ids[0]));
  }
  if (!o.common.address) throw UsageError("archive show: needs a version id or --address N");
  return unwrap(a.current(station_of(o.common, "archive show")));
}

// OLD NEW; OLD alone: against its station's current; none: --address's current against
// the version numbered just below it.
std::pair<storage::VersionWithSet, storage::VersionWithSet> select_diffed(
    storage::ParameterArchive& a, const ArchiveOptions& o) {
  if (o.ids.size() > 2) throw UsageError("archive diff: two version ids at most");
  if (!o.ids.empty() && o.common.address) {
    throw UsageError("archive diff: give version ids or --address, not both");
  }
  if (o.ids.size() == 2) return {unwrap(a.get(o.ids[0])), unwrap(a.get(o.ids[1]))};
  if (o.ids.size() == 1) {
    auto old_version = unwrap(a.get(o.ids[0]));
    auto current = unwrap(a.current(old_version.version.station));
    return {std::move(old_version), std::move(current)};
  }
  if (!o.common.address) throw UsageError("archive diff: needs version ids or --address N");
  const auto station = station_of(o.common, "archive diff");
  auto current = unwrap(a.current(station));
  std::optional<storage::VersionId> previous;
  for (const auto& v : unwrap(a.history(station))) {
    if (v.number < current.version.number) previous = v.id;
  }
  if (!previous) {
    throw ArchiveCommandError("station " + station_text(station) +
                              " has no version before its current one");
  }
  return {unwrap(a.get(*previous)), std::move(current)};
}

// The archive keeps a set in the transfer form, whose identity is zero (the device owns it,
// docs/rs4-scanner.md); the version records the device it came from. Shown one way: the
// parameters name the device the header names, not "device type 0 / serial 0".
DecodedSet with_identity(DecodedSet decoded, storage::ParameterArchive& a,
                         const storage::VersionInfo& v) {
  if (!decoded.set || decoded.set->identity != rs4::scanner::Identity{}) return decoded;
  auto& id = decoded.set->identity;
  id.serial_number = static_cast<std::uint32_t>(std::strtoul(v.serial_number.c_str(), nullptr, 10));
  for (const auto& s : unwrap(a.stations())) {
    if (s.key == v.station) {
      id.device_type = static_cast<std::uint16_t>(std::strtoul(s.device_type.c_str(), nullptr, 0));
    }
  }
  return decoded;
}

}  // namespace

int run_show(const ArchiveOptions& o) {
  auto a = open_archive(o.common, OpenMode::kReadOnly);
  const auto v = select_shown(*a, o);
  const bool is_current = current_of(*a, v.version.station) == v.version.id;
  const auto decoded = decode_set(v.set);
  const auto shown = with_identity(decoded, *a, v.version);
  if (!o.svg.empty()) {
    const auto set = require_set(v);
    write_file_atomically(
        o.svg, rs4::report::field_svg(
                   set, "station " + station_text(v.version.station) + ", " + describe(v.version)));
  }
  if (o.common.json) {
    JsonWriter w(2);
    w.begin_object().field("archive", archive_shown(o.common)).key("version");
    write_version(w, v.version);
    w.field("current", is_current).key("set").begin_object();
    w.field("id", v.set.id).field("size", v.set.blob.size()).field("crc32", crc_hex(v.set.crc32));
    // The stored summary only when it says something the decoded parameters do not.
    const std::string summary = decoded.set ? rs4::report::summary_json(*decoded.set) : "";
    if (v.set.summary != summary) w.field("stored_summary", v.set.summary);
    w.end_object().key("parameters");
    if (shown.set) {
      w.raw(rs4::report::summary_json(*shown.set));
    } else {
      w.null().field("decode_error", decoded.error);
    }
    if (!o.svg.empty()) w.field("svg", o.svg);
    std::cout << w.end_object().str() << "\n";
    return 0;
  }
  print_version(v, is_current);
  if (shown.set) {
    std::cout << "parameters\n" << rs4::report::summary_text(*shown.set);
  } else {
    std::cout << "parameters: " << decoded.error << "\n";
  }
  if (!o.svg.empty()) std::cout << "picture written to " << o.svg << "\n";
  return 0;
}

int run_diff(const ArchiveOptions& o) {
  auto a = open_archive(o.common, OpenMode::kReadOnly);
  const auto [old_v, new_v] = select_diffed(*a, o);
  const auto old_set = require_set(old_v);
  const auto new_set = require_set(new_v);
  const auto d = rs4::report::diff(old_set, new_set);
  if (!o.svg.empty()) {
    const std::string old_label = "version " + std::to_string(old_v.version.id);
    const std::string new_label = "version " + std::to_string(new_v.version.id);
    const std::string title = describe(old_v.version) + " -> " + describe(new_v.version);
    write_file_atomically(
        o.svg, rs4::report::field_diff_svg(old_set, new_set, {title, old_label, new_label}));
  }
  if (o.common.json) {
    JsonWriter w(2);
    w.begin_object().field("archive", archive_shown(o.common)).key("old");
    write_version(w, old_v.version);
    w.key("new");
    write_version(w, new_v.version);
    w.field("same_set", old_v.set.id == new_v.set.id).key("diff").raw(rs4::report::render_json(d));
    if (!o.svg.empty()) w.field("svg", o.svg);
    std::cout << w.end_object().str() << "\n";
    return 0;
  }
  std::cout << describe(old_v.version) << " -> " << describe(new_v.version) << "\n"
            << rs4::report::render_text(d);
  if (!o.svg.empty()) std::cout << "picture written to " << o.svg << "\n";
  return 0;
}

}  // namespace rs4sim::app::archive
