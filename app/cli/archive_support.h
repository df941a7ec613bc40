#pragma once
// Shared by the `rs4sim archive` sub-commands (docs/archive-cli.md): the common options
// (--archive, --json, the station), opening the archive, turning a storage failure into
// an exception main() reports (exit 1), decoding a stored set, and the JSON/text spelling
// of the archive's values.

#include "app/cli/command.h"
#include "rs4/report/json_writer.h"
#include "rs4/scanner/parameter_set.h"
#include "storage/parameter_archive.h"

#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

namespace rs4sim::app::archive {

// Options every sub-command has. The station is --bus NAME (default "default") and
// --address N; versions are addressed by their archive-wide id (the ID column).
struct CommonOptions {
  std::string archive;  // --archive FILE|URI; empty: storage::default_archive_path()
  bool json = false;
  std::string bus = "default";
  std::optional<int> address;
};

void add_archive_option(CLI::App& cmd, CommonOptions& o);
void add_json_option(CLI::App& cmd, CommonOptions& o);
void add_station_options(CLI::App& cmd, CommonOptions& o);

std::string archive_path(const CommonOptions& o);   // what is opened: a file or a URI
std::string archive_shown(const CommonOptions& o);  // what is printed: a URI without password
// The station from --bus/--address; UsageError when --address is missing or not 0..126.
storage::StationKey station_of(const CommonOptions& o, const char* command);

enum class OpenMode : std::uint8_t {
  kReadOnly,       // the file (or the server's archive) must exist; nothing is written
  kWrite,          // the file must exist
  kCreateOrWrite,  // created when missing (import)
};
std::unique_ptr<storage::ParameterArchive> open_archive(const CommonOptions& o, OpenMode mode);

// A storage failure as an exception main() prints ("rs4sim: error: ...", exit 1).
struct ArchiveCommandError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
template <class T>
T unwrap(storage::Result<T> result) {
  if (result.has_error()) throw ArchiveCommandError(result.error().message);
  if constexpr (!std::is_void_v<T>) return std::move(result).value();
}

// The stored blob decoded and validated as an RS4 parameter set; the error text otherwise.
struct DecodedSet {
  std::optional<rs4::scanner::ParameterSet> set;
  std::string error;
};
DecodedSet decode_set(const storage::ParameterSetRecord& record);
// Same, but an undecodable set is an error (needed for a diff or a picture).
rs4::scanner::ParameterSet require_set(const storage::VersionWithSet& v);
// An RS4 set about to become current whose protective field has segments left unset:
// ArchiveCommandError "WHAT: field pair N: ..." unless `allow` (--allow-partial-field).
void refuse_partial_field(std::span<const std::uint8_t> blob, bool allow, const std::string& what);

std::string source_name(storage::VersionSource s);       // "upload", "download", ...
std::string direction_name(storage::SyncDirection d);    // "none", "upload", ...
std::string outcome_name(storage::SyncOutcome o);        // "succeeded", "failed", "aborted"
std::string iso_time(storage::Timestamp t);              // "2026-12-01T20:43:12.345Z"
std::string table_time(storage::Timestamp t);            // "2026-12-01 20:43:12"
std::string crc_hex(std::uint32_t crc);                  // "0x1A2B3C4D"
std::string station_text(const storage::StationKey& s);  // "default/4"
// Who stored a version: "jdoe@ws-maint-03", "jdoe", "@ws-maint-03" or "".
std::string author_text(const storage::VersionInfo& v);
storage::Timestamp now();

void write_version(rs4::report::JsonWriter& w, const storage::VersionInfo& v);
// What a command that changed one version prints: with --json `{archive, version}`, else
// `text`.
void print_changed_version(const CommonOptions& o, const storage::VersionInfo& v,
                           const std::string& text);
void write_station_key(rs4::report::JsonWriter& w, const storage::StationKey& s);

// Writes `text` to `path` through a temporary file in the same directory and a rename,
// so a reader never sees half a file; ArchiveCommandError on failure.
void write_file_atomically(const std::string& path, std::string_view text);

}  // namespace rs4sim::app::archive
