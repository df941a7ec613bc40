// The proxy's retentive state (ParameterArchive::save_proxy_state / load_proxy_state).
#include "storage/request_check.h"
#include "storage/sqlite_archive.h"
#include "storage/time_ms.h"

#include <sqlite3.h>

#include <string>

namespace rs4sim::storage {

using sqlite::Transaction;

Result<void> SqliteArchive::save_proxy_state(const StationKey& station,
                                             std::span<const std::uint8_t> state, Timestamp at) {
  return with_context("save proxy state of " + label(station), [&]() -> Result<void> {
    BOOST_OUTCOME_TRY(check_proxy_state(station, state));
    BOOST_OUTCOME_TRY(tx, Transaction::begin(*db_));
    BOOST_OUTCOME_TRY(s,
                      db_->statement("INSERT INTO proxy_state (bus, address, state, saved_at_ms) "
                                     "VALUES (?, ?, ?, ?) ON CONFLICT (bus, address) DO UPDATE "
                                     "SET state = excluded.state, "
                                     "saved_at_ms = excluded.saved_at_ms"));
    s->bind(1, station.bus);
    s->bind(2, std::int64_t{station.address});
    s->bind(3, state);
    s->bind(4, to_ms(at));
    if (const int rc = s->step(); rc != SQLITE_DONE) return db_->error(rc, label(station));
    return tx.commit();
  });
}

Result<std::vector<std::uint8_t>> SqliteArchive::load_proxy_state(const StationKey& station) {
  return with_context("load proxy state of " + label(station),
                      [&]() -> Result<std::vector<std::uint8_t>> {
                        BOOST_OUTCOME_TRY(s, db_->statement("SELECT state FROM proxy_state WHERE "
                                                            "bus = ? AND address = ?"));
                        s->bind(1, station.bus);
                        s->bind(2, std::int64_t{station.address});
                        const int rc = s->step();
                        if (rc == SQLITE_DONE) {
                          return archive_error(ArchiveError::kNotFound,
                                               label(station) + " has no saved proxy state");
                        }
                        if (rc != SQLITE_ROW) return db_->error(rc, label(station));
                        return s->blob(0);
                      });
}

}  // namespace rs4sim::storage
