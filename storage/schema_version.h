#pragma once
// The archive's schema version and owner mark, the same on every engine: schema version N
// means the same tables and columns in SQLite (PRAGMA user_version) and in PostgreSQL (the
// rs4sim_archive table), each in that engine's types (docs/storage.md "Schema").

#include <cstdint>

namespace rs4sim::storage {

inline constexpr std::int64_t kArchiveApplicationId = 0x52533441;  // "RS4A"
inline constexpr std::int64_t kArchiveSchemaVersion = 5;

}  // namespace rs4sim::storage
