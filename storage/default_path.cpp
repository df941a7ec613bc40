#include "storage/sqlite_archive.h"

#include <cstdlib>

namespace rs4sim::storage {
namespace {

bool set(const char* value) { return value != nullptr && *value != '\0'; }

}  // namespace

std::filesystem::path default_archive_path(const char* xdg_data_home, const char* home) {
  std::filesystem::path base;
  // The specification says a relative $XDG_DATA_HOME is invalid and must be ignored.
  if (set(xdg_data_home) && std::filesystem::path(xdg_data_home).is_absolute()) {
    base = xdg_data_home;
  } else if (set(home)) {
    base = std::filesystem::path(home) / ".local" / "share";
  } else {
    return "archive.sqlite3";
  }
  return base / "rs4sim" / "archive.sqlite3";
}

std::filesystem::path default_archive_path() {
  return default_archive_path(std::getenv("XDG_DATA_HOME"), std::getenv("HOME"));
}

}  // namespace rs4sim::storage
