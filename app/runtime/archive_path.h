#pragma once
// `--archive` of every command: a SQLite file path. A URL (postgresql://…, file://…) is
// refused with the reason instead of becoming a directory tree of that name with a SQLite
// file inside it; the PostgreSQL archive will give postgresql:// its meaning.

#include "app/runtime/usage_error.h"

#include <cctype>
#include <string>

namespace rs4sim::app {

// True for "scheme://…" (RFC 3986 scheme: a letter, then letters, digits, + - .).
inline bool looks_like_url(const std::string& text) {
  const auto colon = text.find("://");
  if (colon == std::string::npos || colon == 0) return false;
  if (std::isalpha(static_cast<unsigned char>(text[0])) == 0) return false;
  for (std::size_t i = 1; i < colon; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (std::isalnum(c) == 0 && c != '+' && c != '-' && c != '.') return false;
  }
  return true;
}

// `path` as given; throws UsageError for a URL.
inline const std::string& checked_archive_path(const std::string& path) {
  if (looks_like_url(path)) {
    throw UsageError("--archive " + path +
                     ": not a file path; the archive is a SQLite file (e.g. --archive "
                     "bench.sqlite3), a database server is not supported yet");
  }
  return path;
}

}  // namespace rs4sim::app
