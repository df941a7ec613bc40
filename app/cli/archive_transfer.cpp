// `rs4sim archive export|import|restore|verify` (docs/archive-cli.md). The export file is
// storage/archive_file.h's: protobuf binary, or protobuf's JSON mapping.
#include "app/cli/archive_commands.h"
#include "app/runtime/author.h"
#include "app/runtime/whole_file.h"
#include "storage/archive_file.h"
#include "storage/request_check.h"

#include <iostream>
#include <iterator>

namespace rs4sim::app::archive {
namespace {

using rs4::report::JsonWriter;

bool is_json_format(const ArchiveOptions& o, const char* command) {
  if (o.file.empty()) throw UsageError(std::string(command) + ": needs FILE");
  if (o.format == "json") return true;
  if (o.format == "binary") return false;
  if (!o.format.empty()) {
    throw UsageError(std::string(command) + ": --format must be binary or json, got '" + o.format +
                     "'");
  }
  const auto dot = o.file.rfind('.');
  return dot != std::string::npos && o.file.substr(dot) == ".json";
}

std::string read_file(const std::string& path) {
  auto file = read_whole_file(path);
  if (!file) throw ArchiveCommandError("cannot read " + path + ": " + file.error);
  return std::move(file.bytes);
}

}  // namespace

std::size_t version_count(const storage::Snapshot& s) {
  std::size_t n = 0;
  for (const auto& station : s.stations) n += station.versions.size();
  return n;
}

int run_export(const ArchiveOptions& o) {
  const bool json = is_json_format(o, "archive export");
  auto a = open_archive(o.common, OpenMode::kReadOnly);
  const auto snapshot = unwrap(a->export_snapshot(now()));
  if (json) {
    write_file_atomically(o.file, storage::encode_json(snapshot));
  } else {
    const auto bytes = storage::encode_binary(snapshot);
    write_file_atomically(o.file, {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
  }
  const char* format = json ? "json" : "binary";
  if (o.common.json) {
    JsonWriter w(2);
    w.begin_object().field("archive", archive_shown(o.common)).field("file", o.file);
    w.field("format", format).field("stations", snapshot.stations.size());
    w.field("versions", version_count(snapshot)).field("sets", snapshot.sets.size());
    std::cout << w.end_object().str() << "\n";
  } else {
    std::cout << "exported " << snapshot.stations.size() << " stations, " << version_count(snapshot)
              << " versions, " << snapshot.sets.size() << " sets to " << o.file << " (" << format
              << ")\n";
  }
  return 0;
}

// What the import did: the counts, and per station what became of its current set.
void print_import(const ArchiveOptions& o, const storage::ImportSummary& s) {
  if (o.common.json) {
    JsonWriter w(2);
    w.begin_object().field("archive", archive_shown(o.common)).field("file", o.file);
    w.field("stations", s.stations).field("versions", s.versions);
    w.field("versions_present", s.versions_present).field("new_sets", s.new_sets);
    w.field("sync_log_entries", s.sync_log_entries).field("sync_log_present", s.sync_log_present);
    w.key("per_station").begin_array();
    for (const auto& st : s.per_station) {
      w.begin_object().field("station", station_text(st.key));
      w.field("versions_added", st.versions_added).field("versions_present", st.versions_present);
      w.field("current", to_string(st.current)).field("current_version", st.current_number);
      w.end_object();
    }
    std::cout << w.end_array().end_object().str() << "\n";
    return;
  }
  std::cout << "imported from " << o.file << ": added " << s.versions << " versions ("
            << s.new_sets << " new sets), " << s.versions_present << " already present; sync log "
            << s.sync_log_entries << " added, " << s.sync_log_present << " already present\n";
  for (const auto& st : s.per_station) {
    std::cout << "  " << station_text(st.key) << ": added " << st.versions_added
              << ", already present " << st.versions_present << ", " << to_string(st.current);
    if (st.current_number != 0) std::cout << " (current #" << st.current_number << ")";
    std::cout << "\n";
  }
}

int run_import(const ArchiveOptions& o) {
  const bool json = is_json_format(o, "archive import");
  const std::string content = read_file(o.file);
  // Decode (and so validate) before the archive is opened: a bad file creates nothing.
  auto decoded = json
                     ? storage::decode_json(content)
                     : storage::decode_binary(
                           {reinterpret_cast<const std::uint8_t*>(content.data()), content.size()});
  if (decoded.has_error()) {
    throw ArchiveCommandError("import " + o.file + ": " + decoded.error().message);
  }
  for (const auto* set : storage::current_sets(decoded.value())) {
    refuse_partial_field(set->blob, o.allow_partial_field, "import " + o.file);
  }
  auto a = open_archive(o.common, OpenMode::kCreateOrWrite);
  auto imported = a->import_snapshot(decoded.value(), storage::ImportOptions{o.make_current});
  if (imported.has_error()) {
    throw ArchiveCommandError("import " + o.file + ": " + imported.error().message);
  }
  print_import(o, imported.value());
  return 0;
}

int run_restore(const ArchiveOptions& o) {
  if (o.ids.size() != 1) throw UsageError("archive restore: needs exactly one version id");
  auto a = open_archive(o.common, OpenMode::kWrite);
  refuse_partial_field(unwrap(a->get(o.ids[0])).set.blob, o.allow_partial_field,
                       "restore " + std::to_string(o.ids[0]));
  const auto v = unwrap(a->restore(o.ids[0], now(), o.note, local_author(o.user)));
  print_changed_version(o.common, v,
                        "version " + std::to_string(v.id) + " (" + station_text(v.station) +
                            " #" + std::to_string(v.number) + ") restores version " +
                            std::to_string(o.ids[0]) +
                            ": current, pending download at the station's next sync");
  return 0;
}

int run_note(const ArchiveOptions& o) {
  if (const auto ok = storage::check_note(o.note); !ok) {
    throw UsageError("archive note: " + ok.error().message);
  }
  auto a = open_archive(o.common, OpenMode::kWrite);
  const auto v = unwrap(a->annotate(o.version, o.note));
  print_changed_version(o.common, v,
                        "version " + std::to_string(v.id) + " (" + station_text(v.station) +
                            " #" + std::to_string(v.number) + "): note " +
                            (v.note.empty() ? "cleared" : "\"" + v.note + "\""));
  return 0;
}

// Creates the archive (a SQLite file, or the tables in a server's schema) or brings an older
// one to this rs4sim's schema; an archive already current is left as it is.
int run_init(const ArchiveOptions& o) {
  auto a = open_archive(o.common, OpenMode::kCreateOrWrite);
  const auto stations = unwrap(a->stations()).size();
  if (o.common.json) {
    JsonWriter w(2);
    w.begin_object().field("archive", archive_shown(o.common)).field("stations", stations);
    std::cout << w.end_object().str() << "\n";
  } else {
    std::cout << "archive " << archive_shown(o.common) << ": ready (" << stations
              << " stations)\n";
  }
  return 0;
}

int run_verify(const ArchiveOptions& o) {
  auto a = open_archive(o.common, OpenMode::kReadOnly);
  const auto report = unwrap(a->check_integrity());
  const auto stations = unwrap(a->stations()).size();
  if (o.common.json) {
    JsonWriter w(2);
    w.begin_object().field("archive", archive_shown(o.common)).field("ok", report.ok());
    w.field("stations", stations).key("problems").begin_array();
    for (const auto& p : report.problems) w.value(p);
    std::cout << w.end_array().end_object().str() << "\n";
  } else if (report.ok()) {
    std::cout << "archive " << archive_shown(o.common) << ": ok (" << stations << " stations)\n";
  } else {
    std::cerr << "archive " << archive_shown(o.common) << ": " << report.problems.size()
              << " problem(s)\n";
    for (const auto& p : report.problems) std::cerr << "  " << p << "\n";
  }
  return report.ok() ? 0 : 1;
}

}  // namespace rs4sim::app::archive
