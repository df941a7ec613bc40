// `rs4sim archive list|show|history|diff|export|import|copy|restore|note|watch|verify|init`: the
// parameter
// archive (docs/storage.md) for people and scripts (docs/archive-cli.md).
#include "app/cli/archive_commands.h"
#include "app/cli/command.h"

#include <memory>

namespace rs4sim::app {
namespace {

using archive::ArchiveOptions;

void no_options(CLI::App&, ArchiveOptions&) {}

// Every archive sub-command: --archive FILE and --json.
void common_options(CLI::App& sub, ArchiveOptions& o) {
  archive::add_archive_option(sub, o.common);
  archive::add_json_option(sub, o.common);
}

void history_options(CLI::App& sub, ArchiveOptions& o) {
  archive::add_station_options(sub, o.common);
  sub.add_option("--sync-log", o.sync_entries, "newest sync log entries shown")
      ->capture_default_str();
}

void show_options(CLI::App& sub, ArchiveOptions& o) {
  sub.add_option("ID", o.ids, "version id (the ID column); without it: the station's current");
  archive::add_station_options(sub, o.common);
  sub.add_option("--svg", o.svg, "also write an SVG picture of the field pairs to FILE");
}

void diff_options(CLI::App& sub, ArchiveOptions& o) {
  sub.add_option("ID", o.ids,
                 "OLD NEW: two version ids; OLD alone: against its station's current; none: "
                 "the station's current against its previous version (--address)");
  archive::add_station_options(sub, o.common);
  sub.add_option("--svg", o.svg, "also write an SVG picture of both versions to FILE");
}

void file_options(CLI::App& sub, ArchiveOptions& o) {
  sub.add_option("FILE", o.file, "the export file (.json: protobuf JSON; else binary)");
  sub.add_option("--format", o.format, "binary or json (default: by the file's extension)");
}

constexpr const char* kPartialFieldHelp =
    "accept an RS4 set whose protective field has segments left unset (0 mm: no protective "
    "field on those beams); without it such a set is not made current";
constexpr const char* kMakeCurrentHelp =
    "the file's current version of each station becomes its current one (never over a newer "
    "restore pending download); without it the history grows and the current sets stay";

void import_options(CLI::App& sub, ArchiveOptions& o) {
  file_options(sub, o);
  sub.add_flag("--allow-partial-field", o.allow_partial_field, kPartialFieldHelp);
  sub.add_flag("--make-current", o.make_current, kMakeCurrentHelp);
}

void copy_options(CLI::App& sub, ArchiveOptions& o) {
  sub.add_option("--from", o.from, "the archive copied from (a SQLite file or PostgreSQL URI)");
  sub.add_option("--to", o.to, "the archive copied into (created when it is a missing file)");
}

void restore_options(CLI::App& sub, ArchiveOptions& o) {
  sub.add_option("ID", o.ids, "the version id to restore (the ID column)");
  sub.add_option("--note", o.note, "note stored with the new version");
  sub.add_option("--user", o.user, "the user the new version records (default: the OS user)");
  sub.add_flag("--allow-partial-field", o.allow_partial_field, kPartialFieldHelp);
}

void list_options(CLI::App& sub, ArchiveOptions& o) {
  sub.add_option("--site", o.site, "only the stations of this site");
  sub.add_option("--line", o.line, "only the stations of this line");
}

void note_options(CLI::App& sub, ArchiveOptions& o) {
  sub.add_option("ID", o.version, "the version id (the ID column)")->required();
  sub.add_option("TEXT", o.note, "the comment; replaces the version's note (\"\" clears it)")
      ->required();
}

void watch_options(CLI::App& sub, ArchiveOptions& o) {
  sub.add_option("--after", o.after,
                 "print the versions stored after this id first (default: only new ones)");
  sub.add_option("--count", o.count, "exit after this many versions (default: until Ctrl-C)");
  sub.add_option("--timeout", o.timeout_s,
                 "exit 1 when --count versions have not come within SECONDS");
}

constexpr SubCommand<ArchiveOptions> kSubCommands[] = {
    {"list", "Stations with their current version", list_options, archive::run_list},
    {"history", "Versions and sync log of one station", history_options, archive::run_history},
    {"show", "One version with its decoded parameters", show_options, archive::run_show},
    {"diff", "Field-level difference of two versions", diff_options, archive::run_diff},
    {"export", "Write the whole archive to a file", file_options, archive::run_export},
    {"import", "Add an export file's history (what is already there is not added again)",
     import_options, archive::run_import},
    {"copy", "Add one archive's whole history to another, verified (SQLite <-> PostgreSQL)",
     copy_options, archive::run_copy},
    {"restore", "Make an old version current again (pending download)", restore_options,
     archive::run_restore},
    {"note", "Replace a version's comment", note_options, archive::run_note},
    {"watch", "Print every version as it is stored (from any master or workstation)",
     watch_options, archive::run_watch},
    {"verify", "Integrity check of the archive (exit 1 on problems)", no_options,
     archive::run_verify},
    {"init", "Create an empty archive (a SQLite file, or the tables in a PostgreSQL database)",
     no_options, archive::run_init},
};

const CommandRegistration kRegistration{
    "archive", "The parameter archive: list, show, history, diff, export, import, copy, restore, "
    "note, watch, verify, init",
    [](CLI::App& cmd) -> Action { return sub_commands(cmd, kSubCommands, common_options); }};

}  // namespace
}  // namespace rs4sim::app
