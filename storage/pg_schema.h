#pragma once
// The PostgreSQL archive's schema and its forward migrations (docs/storage.md "Schema").
// The tables live in the connection's current schema (the first of its search_path, `public`
// unless the URI sets `options=-csearch_path=...`); the rs4sim_archive table marks them as
// ours and holds the schema version. Migrations run in one transaction under an advisory
// lock, so masters starting at once against an empty database create it once.

#include "storage/errors.h"
#include "storage/pg_db.h"

namespace rs4sim::storage::pg {

// Checks that the current schema is ours (or empty) and not newer, then migrates it to
// kArchiveSchemaVersion. A read-only connection must already be at that version.
Result<void> prepare_schema(Connection& c, bool read_only);

}  // namespace rs4sim::storage::pg
