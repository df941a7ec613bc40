// `rs4sim archive watch`: every version as it is stored, by any master or workstation on the
// same archive (storage/change_feed.h; docs/archive-cli.md "watch").
#include "app/cli/archive_commands.h"
#include "storage/change_feed.h"

#include <chrono>
#include <iostream>

namespace rs4sim::app::archive {
namespace {

using rs4::report::JsonWriter;

// One line a version: "2026-12-03 12:50:01  demo/4 #3  id 17  upload  0x1A2B3C4D  serial number 1001
// by jdoe@ws-7: note".
std::string version_line(const storage::VersionInfo& v) {
  std::string line = table_time(v.at) + "  " + station_text(v.station) + " #" +
                     std::to_string(v.number) + "  id " + std::to_string(v.id) + "  " +
                     source_name(v.source) + "  " + crc_hex(v.crc32);
  if (!v.serial_number.empty()) line += "  serial number " + v.serial_number;
  if (v.pending_download) line += "  pending download";
  if (const auto by = author_text(v); !by.empty()) line += "  by " + by;
  if (!v.note.empty()) line += ": " + v.note;
  return line;
}

}  // namespace

int run_watch(const ArchiveOptions& o) {
  if (o.timeout_s < 0) throw UsageError("archive watch: --timeout must not be negative");
  if (o.timeout_s > 0 && o.count == 0) {
    throw UsageError("archive watch: --timeout needs --count (what must come in time)");
  }
  if (o.after && *o.after < 0) throw UsageError("archive watch: --after must not be negative");
  storage::FeedOptions options;
  options.after = o.after;
  auto feed = unwrap(storage::open_change_feed(archive_path(o.common), options));
  if (!o.common.json) {
    std::cout << "watching " << archive_shown(o.common)
              << (o.after ? " from version id " + std::to_string(*o.after) : "") << std::endl;
  }
  using Clock = std::chrono::steady_clock;
  const auto deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(
                         std::chrono::duration<double>(o.timeout_s > 0 ? o.timeout_s : 0));
  std::size_t seen = 0;
  for (;;) {
    auto wait = std::chrono::milliseconds{1000};
    if (o.timeout_s > 0) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
      if (left.count() <= 0) {
        std::cerr << "rs4sim: archive watch: " << seen << " of " << o.count
                  << " versions within " << o.timeout_s << " s" << std::endl;
        return 1;
      }
      wait = std::min(wait, left);
    }
    for (const auto& v : unwrap(feed->next(wait))) {
      if (o.common.json) {
        JsonWriter w(0);
        write_version(w, v);
        std::cout << w.str() << "\n";
      } else {
        std::cout << version_line(v) << "\n";
      }
      std::cout.flush();
      if (o.count != 0 && ++seen == o.count) return 0;
    }
  }
}

}  // namespace rs4sim::app::archive
