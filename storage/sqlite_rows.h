#pragma once
// Row readers shared by the SqliteArchive source files (internal to storage/).

#include "storage/sqlite_db.h"
#include "storage/time_ms.h"
#include "storage/types.h"

#include <string_view>

namespace rs4sim::storage {

inline constexpr std::string_view kVersionColumns =
    "SELECT v.id, s.bus, s.address, v.number, v.set_id, p.crc32, p.size, v.source, "
    "v.stored_at_ms, v.note, v.restored_from, v.pending_download, v.serial_number, v.user_name, "
    "v.host_name, v.simulated_ms "
    "FROM versions v JOIN stations s ON s.id = v.station_id "
    "JOIN parameter_sets p ON p.id = v.set_id ";

// One row selected with kVersionColumns.
VersionInfo read_version(const sqlite::Statement& s);

}  // namespace rs4sim::storage
