#pragma once
// The SQLite archive's schema and its forward migrations (docs/storage.md "Schema").
// A file is ours when PRAGMA application_id is kApplicationId; PRAGMA user_version is
// the schema version. Migrations run in one BEGIN IMMEDIATE transaction on open.

#include "storage/errors.h"
#include "storage/schema_version.h"
#include "storage/sqlite_db.h"

#include <cstdint>

namespace rs4sim::storage::sqlite {

inline constexpr std::int64_t kApplicationId = kArchiveApplicationId;
inline constexpr std::int64_t kSchemaVersion = kArchiveSchemaVersion;

// Checks that the file is ours and not newer, then migrates it to kSchemaVersion (an
// empty file is created). A read-only connection must already be at kSchemaVersion.
Result<void> prepare_schema(Database& db, bool read_only);

}  // namespace rs4sim::storage::sqlite
