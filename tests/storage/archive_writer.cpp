// Helper process for the crash-safety test (archive_crash_test.cpp): stores distinct sets
// into the archive given on the command line, forever, and after each committed store
// writes "<version id> <crc32>\n" to stdout with one write(2). The test kills it.
//   archive_writer LOCATION SEED     (a SQLite file or a PostgreSQL URI)
#include "storage/open_archive.h"
#include "tests/storage/archive_test_support.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
  using namespace rs4sim::storage;
  if (argc != 3) {
    std::fprintf(stderr, "usage: archive_writer LOCATION SEED\n");
    return 2;
  }
  const auto seed = std::strtoull(argv[2], nullptr, 10);
  auto archive = open_archive(argv[1]);
  if (!archive) {
    std::fprintf(stderr, "%s\n", archive.error().message.c_str());
    return 1;
  }
  const StationKey station{"crash", static_cast<std::uint8_t>(seed % 127)};
  for (std::uint64_t i = 0;; ++i) {
    const auto blob = testing::make_blob(seed * 1'000'000 + i);
    const auto v =
        archive.value()->store(testing::request(station, blob, static_cast<std::int64_t>(i)));
    if (!v) {
      std::fprintf(stderr, "%s\n", v.error().message.c_str());
      return 1;
    }
    const auto line = std::to_string(v.value().id) + " " + std::to_string(v.value().crc32) + "\n";
    if (::write(STDOUT_FILENO, line.data(), line.size()) < 0) return 1;
  }
}
