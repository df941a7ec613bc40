#pragma once
// `--archive` of every command: a SQLite file path, or a PostgreSQL server as libpq's URI
// (postgresql://user@host:port/db?sslmode=..., postgres://...; the PG* environment variables
// fill in what it leaves out). Any other URL (file://, sqlite://, mysql://) is refused with
// the reason instead of becoming a directory tree of that name with a SQLite file inside it.

#include "app/runtime/usage_error.h"
#include "storage/open_archive.h"

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

// `location` as given; throws UsageError for a URL that names no PostgreSQL server.
inline const std::string& checked_archive_path(const std::string& location) {
  if (looks_like_url(location) && !storage::is_server_location(location)) {
    throw UsageError("--archive " + location +
                     ": not an archive location; give a SQLite file path (e.g. --archive "
                     "bench.sqlite3) or a PostgreSQL URI (postgresql://user@host/db)");
  }
  return location;
}

}  // namespace rs4sim::app
