#pragma once
// Row readers and the transaction runners shared by the PgArchive source files (internal to
// storage/).

#include "storage/pg_archive.h"
#include "storage/pg_db.h"
#include "storage/time_ms.h"
#include "storage/types.h"

#include <string>
#include <string_view>
#include <vector>

namespace rs4sim::storage {

// A version row, in the order read_version() reads it; the set's summary and blob follow
// for version_with_set().
constexpr std::string_view kVersionSelect =
    "SELECT v.id, s.bus, s.address, v.number, v.set_id, p.crc32, p.size, v.source, "
    "(extract(epoch FROM v.stored_at) * 1000)::int8, v.note, v.restored_from, "
    "v.pending_download, v.serial_number, v.user_name, v.host_name, v.simulated_ms";
constexpr std::string_view kVersionFrom =
    " FROM versions v JOIN stations s ON s.id = v.station_id "
    "JOIN parameter_sets p ON p.id = v.set_id ";

inline std::string version_query(std::string_view where, bool with_set = false) {
  std::string sql(kVersionSelect);
  if (with_set) sql += ", p.summary, p.blob";
  sql += kVersionFrom;
  sql += where;
  return sql;
}

inline VersionInfo read_version(const pg::Rows& r, int i) {
  VersionInfo v;
  v.id = r.int64(i, 0);
  v.station = StationKey{r.text(i, 1), static_cast<std::uint8_t>(r.int64(i, 2))};
  v.number = static_cast<std::uint32_t>(r.int64(i, 3));
  v.set_id = r.int64(i, 4);
  v.crc32 = static_cast<std::uint32_t>(r.int64(i, 5));
  v.size = static_cast<std::uint32_t>(r.int64(i, 6));
  v.source = static_cast<VersionSource>(r.int64(i, 7));
  v.at = from_ms(r.int64(i, 8));
  v.note = r.text(i, 9);
  if (!r.is_null(i, 10)) v.restored_from = r.int64(i, 10);
  v.pending_download = r.boolean(i, 11);
  v.serial_number = r.text(i, 12);
  v.user = r.text(i, 13);
  v.host = r.text(i, 14);
  if (!r.is_null(i, 15)) v.simulated = std::chrono::milliseconds{r.int64(i, 15)};
  return v;
}

// Every row of version_query(...), in order.
inline std::vector<VersionInfo> read_versions(const pg::Rows& r) {
  std::vector<VersionInfo> out;
  out.reserve(static_cast<std::size_t>(r.count()));
  for (int i = 0; i < r.count(); ++i) out.push_back(read_version(r, i));
  return out;
}

// A row of version_query(..., true).
inline VersionWithSet read_version_with_set(const pg::Rows& r, int i) {
  VersionWithSet out{read_version(r, i), {}};
  out.set = ParameterSetRecord{out.version.set_id, out.version.crc32, r.bytes(i, 17),
                               r.text(i, 16)};
  return out;
}

template <class T, class F>
Result<T> PgArchive::write(F&& body) {
  for (int attempt = 1;; ++attempt) {
    BOOST_OUTCOME_TRY(tx, pg::Transaction::begin(*c_, pg::Transaction::Kind::kWrite));
    Result<T> result = body();
    if (result) {
      auto committed = tx.commit();
      if (committed) return result;
      result = std::move(committed).error();
    }
    const auto& state = c_->last_sqlstate();
    const bool raced = state == pg::kSerializationFailure || state == pg::kDeadlockDetected;
    if (!raced || attempt >= options_.max_attempts) return result;
  }
}

template <class T, class F>
Result<T> PgArchive::read(F&& body) {
  BOOST_OUTCOME_TRY(tx, pg::Transaction::begin(*c_, pg::Transaction::Kind::kRead));
  Result<T> result = body();
  if (!result) return result;
  BOOST_OUTCOME_TRY(tx.commit());
  return result;
}

}  // namespace rs4sim::storage
