#pragma once
// One way to open an archive from what a user types after --archive: a PostgreSQL URI
// ("postgresql://…" or "postgres://…", libpq's syntax) opens PgArchive on that server,
// anything else is a SQLite file path (SqliteArchive). Every command that takes --archive,
// the gRPC Archive service and the proxy open their archive here.

#include "storage/parameter_archive.h"

#include <memory>
#include <string>

namespace rs4sim::storage {

struct OpenOptions {
  bool read_only{false};
};

// True when `location` names a PostgreSQL server rather than a file.
bool is_server_location(const std::string& location) noexcept;
// What messages show of `location`: a file path as it is, a URI without its password.
std::string display_location(const std::string& location);

Result<std::unique_ptr<ParameterArchive>> open_archive(const std::string& location,
                                                       const OpenOptions& options = {});

}  // namespace rs4sim::storage
