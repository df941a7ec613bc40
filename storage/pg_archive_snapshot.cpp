// PgArchive: sync log, integrity check, and the rows RowArchive's export and import read
// (pg_archive.h).
#include "storage/crc32.h"
#include "storage/pg_archive.h"
#include "storage/pg_rows.h"
#include "storage/request_check.h"

#include <algorithm>
#include <map>

namespace rs4sim::storage {

using boost::outcome_v2::success;
using pg::Params;

Result<void> PgArchive::insert_sync(std::int64_t station, const SyncLogEntry& e) {
  Params p;
  p.add(station).add(to_ms(e.at)).add(e.reason).add(static_cast<std::int64_t>(e.direction));
  p.add(static_cast<std::int64_t>(e.outcome)).add(std::int64_t{e.error_number_fb});
  p.add(std::int64_t{e.error_code_sfc}).add(std::int64_t{e.error_number_device});
  p.add(static_cast<std::int64_t>(e.duration.count()));
  BOOST_OUTCOME_TRY(c_->query(
      "INSERT INTO sync_log (station_id, at, reason, direction, outcome, error_number_fb, "
      "error_code_sfc, error_number_device, duration_ms) VALUES ($1::int8, "
      "to_timestamp($2::float8 / 1000), $3::text, $4::int2, $5::int2, $6::int8, $7::int8, "
      "$8::int8, $9::int8)",
      p, "insert sync log entry"));
  return success();
}

Result<std::vector<SyncLogEntry>> PgArchive::sync_rows(std::int64_t station,
                                                       const StationKey& key,
                                                       std::int64_t limit) {
  Params p;
  p.add(station).add(limit);
  BOOST_OUTCOME_TRY(
      r, c_->query("SELECT (extract(epoch FROM at) * 1000)::int8, reason, direction, outcome, "
                   "error_number_fb, error_code_sfc, error_number_device, duration_ms FROM "
                   "(SELECT * FROM sync_log WHERE station_id = $1::int8 ORDER BY id DESC "
                   "LIMIT $2::int8) newest ORDER BY id",
                   p, label(key)));
  std::vector<SyncLogEntry> out;
  out.reserve(static_cast<std::size_t>(r.count()));
  for (int i = 0; i < r.count(); ++i) {
    SyncLogEntry e;
    e.station = key;
    e.at = from_ms(r.int64(i, 0));
    e.reason = r.text(i, 1);
    e.direction = static_cast<SyncDirection>(r.int64(i, 2));
    e.outcome = static_cast<SyncOutcome>(r.int64(i, 3));
    e.error_number_fb = static_cast<std::uint32_t>(r.int64(i, 4));
    e.error_code_sfc = static_cast<std::uint32_t>(r.int64(i, 5));
    e.error_number_device = static_cast<std::uint32_t>(r.int64(i, 6));
    e.duration = std::chrono::milliseconds{r.int64(i, 7)};
    out.push_back(std::move(e));
  }
  return out;
}

// The server keeps its own structures sound (and refuses a row that breaks a constraint);
// what it cannot know is whether a blob still has the CRC-32 and size the archive claims, and
// that a current version belongs to its station. Blobs are read in pages of kPage rows, so the
// check of a large archive does not hold every set in memory at once.
Result<IntegrityReport> PgArchive::check_integrity() {
  return with_context("integrity check", [&]() -> Result<IntegrityReport> {
    return read<IntegrityReport>([&]() -> Result<IntegrityReport> {
      IntegrityReport report;
      constexpr std::int64_t kPage = 256;
      std::int64_t after = 0;
      for (;;) {
        Params p;
        p.add(after).add(kPage);
        BOOST_OUTCOME_TRY(r, c_->query("SELECT id, crc32, size, blob, sha256 = sha256(blob) "
                                       "FROM parameter_sets WHERE id > $1::int8 ORDER BY id "
                                       "LIMIT $2::int8",
                                       p, "read parameter sets"));
        for (int i = 0; i < r.count(); ++i) {
          const auto blob = r.bytes(i, 3);
          const auto id = std::to_string(r.int64(i, 0));
          if (crc32(blob) != static_cast<std::uint32_t>(r.int64(i, 1))) {
            report.problems.push_back("parameter set " + id + ": CRC-32 does not match its blob");
          }
          if (static_cast<std::int64_t>(blob.size()) != r.int64(i, 2)) {
            report.problems.push_back("parameter set " + id + ": size does not match its blob");
          }
          if (!r.boolean(i, 4)) {
            report.problems.push_back("parameter set " + id + ": SHA-256 does not match its blob");
          }
          after = r.int64(i, 0);
        }
        if (r.count() < kPage) break;
      }
      BOOST_OUTCOME_TRY(
          r, c_->query("SELECT c.station_id FROM current_versions c JOIN versions v "
                       "ON v.id = c.version_id WHERE v.station_id <> c.station_id",
                       "check current versions"));
      for (int i = 0; i < r.count(); ++i) {
        report.problems.push_back("station " + std::to_string(r.int64(i, 0)) +
                                  ": current version belongs to another station");
      }
      return report;
    });
  });
}

Result<void> PgArchive::in_write(const Body& body) { return write<void>(body); }

Result<void> PgArchive::in_read(const Body& body) { return read<void>(body); }

Result<std::vector<VersionInfo>> PgArchive::station_versions(std::int64_t station) {
  Params p;
  p.add(station);
  BOOST_OUTCOME_TRY(r, c_->query(version_query("WHERE v.station_id = $1::int8 ORDER BY v.number"),
                                 p, "read versions"));
  return read_versions(r);
}

Result<std::vector<ParameterSetRecord>> PgArchive::all_sets() {
  BOOST_OUTCOME_TRY(sets, c_->query("SELECT id, crc32, blob, summary FROM parameter_sets "
                                    "ORDER BY id",
                                    "read parameter sets"));
  std::vector<ParameterSetRecord> out;
  out.reserve(static_cast<std::size_t>(sets.count()));
  for (int i = 0; i < sets.count(); ++i) {
    out.push_back({sets.int64(i, 0), static_cast<std::uint32_t>(sets.int64(i, 1)),
                   sets.bytes(i, 2), sets.text(i, 3)});
  }
  return out;
}

}  // namespace rs4sim::storage
