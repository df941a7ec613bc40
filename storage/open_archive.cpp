#include "storage/open_archive.h"

#include "storage/pg_archive.h"
#include "storage/pg_db.h"
#include "storage/sqlite_archive.h"

namespace rs4sim::storage {

bool is_server_location(const std::string& location) noexcept {
  return pg::is_postgres_uri(location);
}

std::string display_location(const std::string& location) {
  return is_server_location(location) ? pg::redacted(location) : location;
}

Result<std::unique_ptr<ParameterArchive>> open_archive(const std::string& location,
                                                       const OpenOptions& options) {
  if (is_server_location(location)) {
    PgOptions pg_options;
    pg_options.read_only = options.read_only;
    BOOST_OUTCOME_TRY(archive, PgArchive::open(location, pg_options));
    return std::unique_ptr<ParameterArchive>(std::move(archive));
  }
  SqliteOptions sqlite_options;
  sqlite_options.read_only = options.read_only;
  BOOST_OUTCOME_TRY(archive, SqliteArchive::open(location, sqlite_options));
  return std::unique_ptr<ParameterArchive>(std::move(archive));
}

}  // namespace rs4sim::storage
