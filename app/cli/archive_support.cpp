#include "app/cli/archive_support.h"

#include "app/runtime/archive_path.h"
#include "dp/pdu/sap.h"
#include "rs4/param_doc/field_coverage.h"
#include "rs4/scanner/parameter_codec.h"
#include "storage/open_archive.h"
#include "storage/sqlite_archive.h"  // default_archive_path

#include <unistd.h>

#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace rs4sim::app::archive {

void add_archive_option(CLI::App& cmd, CommonOptions& o) {
  cmd.add_option("--archive", o.archive,
                 "archive: a SQLite file (default: $XDG_DATA_HOME/rs4sim/archive.sqlite3, else "
                 "~/.local/share/rs4sim/archive.sqlite3) or a PostgreSQL URI "
                 "(postgresql://user@host/db)");
}

void add_json_option(CLI::App& cmd, CommonOptions& o) {
  cmd.add_flag("--json", o.json, "print one JSON document instead of tables");
}

void add_station_options(CLI::App& cmd, CommonOptions& o) {
  cmd.add_option("--bus", o.bus, "bus name of the station")->capture_default_str();
  cmd.add_option("--address", o.address,
                 "PROFIBUS address of the station (0.." +
                     std::to_string(dp::pdu::sap::kMaxStationAddress) + ")");
}

std::string archive_path(const CommonOptions& o) {
  return o.archive.empty() ? storage::default_archive_path().string()
                           : checked_archive_path(o.archive);
}

std::string archive_shown(const CommonOptions& o) {
  return storage::display_location(archive_path(o));
}

storage::StationKey station_of(const CommonOptions& o, const char* command) {
  if (!o.address) throw UsageError(std::string(command) + ": needs --address N (the station)");
  if (*o.address < 0 || *o.address > dp::pdu::sap::kMaxStationAddress) {
    throw UsageError(std::string(command) + ": --address must be 0.." +
                     std::to_string(dp::pdu::sap::kMaxStationAddress) + ", got " +
                     std::to_string(*o.address));
  }
  if (o.bus.empty()) throw UsageError(std::string(command) + ": --bus must not be empty");
  return {o.bus, static_cast<std::uint8_t>(*o.address)};
}

std::unique_ptr<storage::ParameterArchive> open_archive(const CommonOptions& o, OpenMode mode) {
  const std::string location = archive_path(o);
  const bool server = storage::is_server_location(location);
  if (!server && mode != OpenMode::kCreateOrWrite && location != ":memory:" &&
      !std::filesystem::exists(location)) {
    throw ArchiveCommandError("no archive at " + location + " (--archive FILE or URI)");
  }
  storage::OpenOptions options;
  options.read_only = mode == OpenMode::kReadOnly;
  auto opened = storage::open_archive(location, options);
  if (opened.has_error()) {
    // The message names the location already, a server without its password.
    std::string text = "archive: " + opened.error().message;
    if (server && opened.error().code == storage::ArchiveError::kNotAnArchive &&
        text.find(storage::kNoArchiveYet) != std::string::npos) {
      text += "; start one with: rs4sim archive init --archive '" +
              storage::display_location(location) + "'";
    }
    if (opened.error().code == storage::ArchiveError::kReadOnly &&
        text.find(storage::kNeedsMigration) != std::string::npos) {
      text += "; bring it to this rs4sim's schema (every row is kept) with: rs4sim archive init "
              "--archive '" + storage::display_location(location) + "'";
    }
    throw ArchiveCommandError(text);
  }
  return std::move(opened).value();
}

DecodedSet decode_set(const storage::ParameterSetRecord& record) {
  auto decoded = rs4::scanner::decode_transfer_form(record.blob);
  if (decoded.has_error()) {
    return {std::nullopt, "not a valid RS4 parameter set: " + decoded.error().message()};
  }
  return {decoded.value(), {}};
}

rs4::scanner::ParameterSet require_set(const storage::VersionWithSet& v) {
  auto decoded = decode_set(v.set);
  if (!decoded.set) {
    throw ArchiveCommandError("version " + std::to_string(v.version.id) + ": " + decoded.error);
  }
  return *decoded.set;
}

void refuse_partial_field(std::span<const std::uint8_t> blob, bool allow, const std::string& what) {
  if (const auto issue = rs4::param_doc::check_stored_set(blob, {allow})) {
    throw ArchiveCommandError(what + ": " + issue->message() + " (--allow-partial-field)");
  }
}

std::string source_name(storage::VersionSource s) { return storage::to_string(s); }

std::string direction_name(storage::SyncDirection d) {
  switch (d) {
    case storage::SyncDirection::kNone: return "none";
    case storage::SyncDirection::kUpload: return "upload";
    case storage::SyncDirection::kDownload: return "download";
    case storage::SyncDirection::kVerify: return "verify";
  }
  return "unknown";
}

std::string outcome_name(storage::SyncOutcome o) {
  switch (o) {
    case storage::SyncOutcome::kSucceeded: return "succeeded";
    case storage::SyncOutcome::kFailed: return "failed";
    case storage::SyncOutcome::kAborted: return "aborted";
  }
  return "unknown";
}

namespace {

std::string format_time(storage::Timestamp t, const char* format, bool with_ms) {
  const auto seconds = std::chrono::floor<std::chrono::seconds>(t);
  const std::time_t unix_seconds = static_cast<std::time_t>(seconds.time_since_epoch().count());
  std::tm tm{};
  ::gmtime_r(&unix_seconds, &tm);
  char b[48];
  const std::size_t n = std::strftime(b, sizeof b, format, &tm);
  std::string out(b, n);
  if (with_ms) {
    std::snprintf(b, sizeof b, ".%03dZ", static_cast<int>((t - seconds).count()));
    out += b;
  }
  return out;
}

}  // namespace

std::string iso_time(storage::Timestamp t) { return format_time(t, "%Y-%m-%dT%H:%M:%S", true); }
std::string table_time(storage::Timestamp t) { return format_time(t, "%Y-%m-%d %H:%M:%S", false); }

std::string crc_hex(std::uint32_t crc) {
  char b[16];
  std::snprintf(b, sizeof b, "0x%08X", crc);
  return b;
}

std::string station_text(const storage::StationKey& s) {
  return s.bus + "/" + std::to_string(s.address);
}

std::string author_text(const storage::VersionInfo& v) {
  return v.host.empty() ? v.user : v.user + "@" + v.host;
}

storage::Timestamp now() {
  return std::chrono::time_point_cast<std::chrono::milliseconds>(std::chrono::system_clock::now());
}

void write_station_key(rs4::report::JsonWriter& w, const storage::StationKey& s) {
  w.field("bus", s.bus).field("address", s.address);
}

void write_version(rs4::report::JsonWriter& w, const storage::VersionInfo& v) {
  w.begin_object().field("id", v.id);
  write_station_key(w, v.station);
  w.field("number", v.number).field("set_id", v.set_id).field("crc32", crc_hex(v.crc32));
  w.field("size", v.size).field("source", source_name(v.source)).field("at", iso_time(v.at));
  w.field("serial_number", v.serial_number).field("note", v.note);
  w.field("user", v.user).field("host", v.host);
  w.key("restored_from");
  if (v.restored_from) {
    w.value(static_cast<std::int64_t>(*v.restored_from));
  } else {
    w.null();
  }
  w.field("pending_download", v.pending_download).end_object();
}

void print_changed_version(const CommonOptions& o, const storage::VersionInfo& v,
                           const std::string& text) {
  if (o.json) {
    rs4::report::JsonWriter w(2);
    w.begin_object().field("archive", archive_shown(o)).key("version");
    write_version(w, v);
    std::cout << w.end_object().str() << "\n";
  } else {
    std::cout << text << "\n";
  }
}

void write_file_atomically(const std::string& path, std::string_view text) {
  const std::string tmp = path + ".tmp-" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.flush();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(tmp, ignored);
      throw ArchiveCommandError("cannot write " + path);
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw ArchiveCommandError("cannot write " + path + ": " + ec.message());
  }
}

}  // namespace rs4sim::app::archive
