// `rs4sim archive list` and `rs4sim archive history` (docs/archive-cli.md).
#include "app/cli/archive_commands.h"
#include "app/cli/archive_table.h"

#include <iostream>

namespace rs4sim::app::archive {
namespace {

using rs4::report::JsonWriter;

std::string latest_serial(const storage::StationInfo& s) {
  return s.serials.empty() ? "" : s.serials.back().serial_number;
}

std::string flags(const storage::VersionInfo& v, std::optional<storage::VersionId> current) {
  std::string out = current == v.id ? "current" : "";
  auto add = [&out](const std::string& flag) { out += (out.empty() ? "" : ", ") + flag; };
  if (v.pending_download) add("pending download");
  if (v.restored_from) add("restores " + std::to_string(*v.restored_from));
  return out;
}

void print_sync_log(const std::vector<storage::SyncLogEntry>& log) {
  if (log.empty()) {
    std::cout << "\nno sync log entries\n";
    return;
  }
  Table t({{"TIME (UTC)"},
           {"REASON"},
           {"DIRECTION"},
           {"OUTCOME"},
           {"FB", true},
           {"SFC", true},
           {"RS4", true},
           {"MS", true}});
  for (const auto& e : log) {
    t.add({table_time(e.at), e.reason, direction_name(e.direction), outcome_name(e.outcome),
           std::to_string(e.error_number_fb), std::to_string(e.error_code_sfc),
           std::to_string(e.error_number_device), std::to_string(e.duration.count())});
  }
  std::cout << "\nsync log (newest " << log.size() << ", oldest first)\n" << t.render();
}

void write_sync_log(JsonWriter& w, const std::vector<storage::SyncLogEntry>& log) {
  w.key("sync_log").begin_array();
  for (const auto& e : log) {
    w.begin_object().field("at", iso_time(e.at)).field("reason", e.reason);
    w.field("direction", direction_name(e.direction)).field("outcome", outcome_name(e.outcome));
    w.field("error_number_fb", e.error_number_fb).field("error_code_sfc", e.error_code_sfc);
    w.field("error_number_rs4", e.error_number_device);
    w.field("duration_ms", e.duration.count()).end_object();
  }
  w.end_array();
}


}  // namespace

std::optional<storage::VersionId> current_of(storage::ParameterArchive& archive,
                                             const storage::StationKey& station) {
  for (const auto& s : unwrap(archive.stations())) {
    if (s.key == station) return s.current;
  }
  return std::nullopt;
}

int run_list(const ArchiveOptions& o) {
  auto a = open_archive(o.common, OpenMode::kReadOnly);
  auto stations = unwrap(a->stations());
  std::erase_if(stations, [&](const storage::StationInfo& s) {
    return (!o.site.empty() && s.site != o.site) || (!o.line.empty() && s.line != o.line);
  });
  JsonWriter w(2);
  w.begin_object().field("archive", archive_shown(o.common)).key("stations").begin_array();
  Table t({{"BUS"},
           {"ADDR", true},
           {"DEVICE TYPE"},
           {"SERIAL NUMBER"},
           {"VERSIONS", true},
           {"CURRENT", true},
           {"NO", true},
           {"CRC32"},
           {"STORED (UTC)"},
           {"SOURCE"},
           {"PENDING"},
           {"SITE"},
           {"LINE"}});
  for (const auto& s : stations) {
    const auto versions = unwrap(a->history(s.key)).size();
    std::optional<storage::VersionWithSet> cur;
    if (s.current) cur = unwrap(a->get(*s.current));
    w.begin_object();
    write_station_key(w, s.key);
    w.field("device_type", s.device_type).field("site", s.site).field("line", s.line);
    w.key("serial_numbers").begin_array();
    for (const auto& serial : s.serials) w.value(serial.serial_number);
    w.end_array().field("versions", versions).key("current");
    if (cur) {
      write_version(w, cur->version);
    } else {
      w.null();
    }
    w.end_object();
    t.add({s.key.bus, std::to_string(s.key.address), s.device_type, latest_serial(s),
           std::to_string(versions), cur ? std::to_string(cur->version.id) : "-",
           cur ? std::to_string(cur->version.number) : "-", cur ? crc_hex(cur->version.crc32) : "",
           cur ? table_time(cur->version.at) : "", cur ? source_name(cur->version.source) : "",
           cur && cur->version.pending_download ? "yes" : "", s.site, s.line});
  }
  w.end_array().end_object();
  if (o.common.json) {
    std::cout << w.str() << "\n";
  } else if (stations.empty()) {
    std::cout << "no stations in " << archive_shown(o.common)
              << (o.site.empty() && o.line.empty() ? "" : " with that site and line") << "\n";
  } else {
    std::cout << t.render();
  }
  return 0;
}

int run_history(const ArchiveOptions& o) {
  const auto station = station_of(o.common, "archive history");
  auto a = open_archive(o.common, OpenMode::kReadOnly);
  const auto versions = unwrap(a->history(station));
  const auto current = current_of(*a, station);
  const auto log = unwrap(a->sync_log(station, o.sync_entries));
  if (o.common.json) {
    JsonWriter w(2);
    w.begin_object().field("archive", archive_shown(o.common)).key("station").begin_object();
    write_station_key(w, station);
    w.end_object().key("current");
    if (current) {
      w.value(static_cast<std::int64_t>(*current));
    } else {
      w.null();
    }
    w.key("versions").begin_array();
    for (const auto& v : versions) write_version(w, v);
    w.end_array();
    write_sync_log(w, log);
    std::cout << w.end_object().str() << "\n";
    return 0;
  }
  Table t({{"ID", true},
           {"NO", true},
           {"STORED (UTC)"},
           {"SOURCE"},
           {"CRC32"},
           {"SIZE", true},
           {"SERIAL NUMBER"},
           {"FLAGS"},
           {"NOTE"},
           {"BY"}});
  for (const auto& v : versions) {
    t.add({std::to_string(v.id), std::to_string(v.number), table_time(v.at), source_name(v.source),
           crc_hex(v.crc32), std::to_string(v.size), v.serial_number, flags(v, current), v.note,
           author_text(v)});
  }
  std::cout << "station " << station_text(station) << ", " << versions.size() << " version"
            << (versions.size() == 1 ? "" : "s") << "\n"
            << t.render();
  print_sync_log(log);
  return 0;
}

}  // namespace rs4sim::app::archive
