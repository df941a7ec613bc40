#pragma once
// The `rs4sim archive` sub-commands (docs/archive-cli.md). Each returns the exit code;
// usage errors throw UsageError (exit 2), archive and file errors ArchiveCommandError
// (exit 1). Nothing is written to the archive unless the command succeeds.

#include "app/cli/archive_support.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace rs4sim::app::archive {

struct ArchiveOptions {
  CommonOptions common;
  std::vector<storage::VersionId> ids;  // positional version ids
  storage::VersionId version = 0;       // note: the one version id
  std::string svg;                      // show/diff: --svg FILE
  std::string file;                     // export/import: the file
  std::string format;                   // export/import: "binary", "json" or "" (by extension)
  bool make_current = false;            // import: --make-current
  bool allow_partial_field = false;     // import, restore: --allow-partial-field
  std::string note;                     // restore: --note; note: the TEXT
  std::string user;                     // restore: --user (default: the OS user)
  std::string site;                     // list: --site filter
  std::string line;                     // list: --line filter
  std::size_t count = 0;                // watch: --count N (0: until interrupted)
  std::optional<storage::VersionId> after;  // watch: --after ID (default: the newest now)
  double timeout_s = 0;                 // watch: --timeout SECONDS (0: none)
  std::size_t sync_entries = 20;        // history: --sync-log N
  std::string from;                     // copy: --from ARCHIVE
  std::string to;                       // copy: --to ARCHIVE
};

int run_list(const ArchiveOptions& o);
int run_history(const ArchiveOptions& o);
int run_show(const ArchiveOptions& o);
int run_diff(const ArchiveOptions& o);
int run_export(const ArchiveOptions& o);
int run_import(const ArchiveOptions& o);
int run_restore(const ArchiveOptions& o);
int run_note(const ArchiveOptions& o);
int run_watch(const ArchiveOptions& o);
int run_verify(const ArchiveOptions& o);
int run_copy(const ArchiveOptions& o);

// Every station's versions in `s`.
std::size_t version_count(const storage::Snapshot& s);

// `archive init`: creates an empty archive (or brings an older one to this schema).
int run_init(const ArchiveOptions& o);

// The station's current version id, if it has one.
std::optional<storage::VersionId> current_of(storage::ParameterArchive& archive,
                                             const storage::StationKey& station);

}  // namespace rs4sim::app::archive
