// PgArchive: open, the rows every call shares, store, read, restore (pg_archive.h).
//
// Why READ COMMITTED is enough for a change: every change that adds a version first takes the
// station's row lock (the upsert of store(), SELECT ... FOR UPDATE of restore() and import),
// and numbers the version with a statement that runs after the lock is granted, so it sees the
// version a concurrent writer committed before it: two masters on one station cannot number a
// version twice (the UNIQUE (station_id, number) constraint would refuse it anyway). A new set
// is inserted with ON CONFLICT (sha256) DO NOTHING and read back otherwise: a concurrent insert
// of the same bytes makes the second wait and then find the first's row, never a second copy.
#include "storage/pg_archive.h"

#include "storage/pg_rows.h"
#include "storage/pg_schema.h"
#include "storage/request_check.h"
#include "storage/time_ms.h"

namespace rs4sim::storage {

using boost::outcome_v2::success;
using pg::Params;
using pg::Rows;
using pg::Transaction;


Result<std::unique_ptr<PgArchive>> PgArchive::open(const std::string& conninfo,
                                                   const PgOptions& options) {
  return with_context("open " + pg::redacted(conninfo), [&]() -> Result<std::unique_ptr<PgArchive>> {
    BOOST_OUTCOME_TRY(c, pg::Connection::open(conninfo));
    if (options.read_only) {
      BOOST_OUTCOME_TRY(c->exec("SET default_transaction_read_only = on", "read-only session"));
    }
    BOOST_OUTCOME_TRY(pg::prepare_schema(*c, options.read_only));
    return std::unique_ptr<PgArchive>(new PgArchive(std::move(c), options));
  });
}

Result<std::int64_t> PgArchive::station_id(const StationKey& key, bool lock) {
  Params p;
  p.add(key.bus).add(std::int64_t{key.address});
  BOOST_OUTCOME_TRY(r, c_->query(lock ? "SELECT id FROM stations WHERE bus = $1::text AND "
                                        "address = $2::int2 FOR UPDATE"
                                      : "SELECT id FROM stations WHERE bus = $1::text AND "
                                        "address = $2::int2",
                                 p, label(key)));
  if (r.count() == 1) return r.int64(0, 0);
  auto failure = archive_error(ArchiveError::kUnknownStation, label(key));
  failure.message += " (" + known_stations() + ")";
  return failure;
}

// "the archive has bus demo: 4, 5; bus line2: 7" (or that it has none), as SqliteArchive.
std::string PgArchive::known_stations() {
  auto r = c_->query(
      "SELECT bus, string_agg(address::text, ', ' ORDER BY address) FROM stations "
      "GROUP BY bus ORDER BY bus COLLATE \"C\"",
      "list stations");
  if (!r) return "the archive's stations could not be read";
  std::string text;
  for (int i = 0; i < r.value().count(); ++i) {
    text += (text.empty() ? "the archive has bus " : "; bus ") + r.value().text(i, 0) + ": " +
            r.value().text(i, 1);
  }
  return text.empty() ? "the archive holds no stations yet" : text;
}

Result<std::int64_t> PgArchive::upsert_station(const StationKey& key,
                                               std::string_view device_type,
                                               std::string_view site, std::string_view line) {
  Params p;
  p.add(key.bus).add(std::int64_t{key.address}).add(device_type).add(site).add(line);
  // DO UPDATE (not DO NOTHING) so that the row is locked for the rest of the transaction.
  BOOST_OUTCOME_TRY(
      r, c_->query("INSERT INTO stations (bus, address, device_type, site, line) "
                   "VALUES ($1::text, $2::int2, $3::text, $4::text, $5::text) "
                   "ON CONFLICT (bus, address) DO UPDATE SET "
                   "device_type = CASE WHEN excluded.device_type <> '' "
                   "THEN excluded.device_type ELSE stations.device_type END, "
                   "site = CASE WHEN excluded.site <> '' THEN excluded.site "
                   "ELSE stations.site END, "
                   "line = CASE WHEN excluded.line <> '' THEN excluded.line "
                   "ELSE stations.line END RETURNING id",
                   p, "write " + label(key)));
  return r.int64(0, 0);
}

Result<void> PgArchive::see_serial(std::int64_t station, std::string_view serial,
                                   Timestamp first, Timestamp last) {
  if (serial.empty()) return success();
  Params p;
  p.add(station).add(serial).add(to_ms(first)).add(to_ms(last));
  BOOST_OUTCOME_TRY(c_->query(
      "INSERT INTO station_serials VALUES ($1::int8, $2::text, to_timestamp($3::float8 / 1000), "
      "to_timestamp($4::float8 / 1000)) ON CONFLICT (station_id, serial_number) DO UPDATE SET "
      "first_seen = least(station_serials.first_seen, excluded.first_seen), "
      "last_seen = greatest(station_serials.last_seen, excluded.last_seen)",
      p, "record serial number " + std::string(serial)));
  return success();
}

// Looked up first: a set stored again (the common case) costs one statement and no identity
// value (an INSERT that meets a conflict still draws one).
Result<SetId> PgArchive::intern_set(std::span<const std::uint8_t> blob, std::uint32_t crc,
                                    std::string_view summary, bool& inserted) {
  inserted = false;
  Params q;
  q.add(blob);
  constexpr std::string_view kFind =
      "SELECT id, blob = $1::bytea FROM parameter_sets WHERE sha256 = sha256($1::bytea)";
  const auto found = [&](const Rows& r) -> Result<SetId> {
    if (!r.boolean(0, 1)) {
      return archive_error(ArchiveError::kCorruptArchive,
                           "a stored parameter set has this set's SHA-256 but other bytes");
    }
    return r.int64(0, 0);
  };
  {
    BOOST_OUTCOME_TRY(r, c_->query(kFind, q, "look up parameter set"));
    if (r.count() == 1) return found(r);
  }
  Params p;
  p.add(std::int64_t{crc}).add(static_cast<std::int64_t>(blob.size())).add(blob).add(summary);
  BOOST_OUTCOME_TRY(r, c_->query("INSERT INTO parameter_sets (crc32, size, sha256, blob, summary) "
                                 "VALUES ($1::int8, $2::int4, sha256($3::bytea), $3::bytea, "
                                 "$4::text) ON CONFLICT (sha256) DO NOTHING RETURNING id",
                                 p, "insert parameter set"));
  if (r.count() == 1) {
    inserted = true;
    return r.int64(0, 0);
  }
  // A concurrent writer inserted the same bytes and committed while this insert waited.
  BOOST_OUTCOME_TRY(again, c_->query(kFind, q, "look up parameter set"));
  if (again.count() != 1) {
    return archive_error(ArchiveError::kCorruptArchive, "a parameter set vanished while stored");
  }
  return found(again);
}

Result<VersionId> PgArchive::append_version(std::int64_t station, const NewVersion& v) {
  Params p;
  p.add(station).add(v.set_id).add(static_cast<std::int64_t>(v.source)).add(to_ms(v.at));
  p.add(v.note).add(v.serial_number);
  if (v.restored_from) {
    p.add(*v.restored_from);
  } else {
    p.add_null();
  }
  p.add_bool(v.pending_download);
  p.add(v.user).add(v.host);
  if (v.simulated) {
    p.add(static_cast<std::int64_t>(v.simulated->count()));
  } else {
    p.add_null();
  }
  // Numbered under the station's row lock, which the caller holds. The change feed's
  // notification (change_feed.h) is queued in the same transaction: PostgreSQL delivers it
  // at the commit, never for a version rolled back.
  BOOST_OUTCOME_TRY(
      r, c_->query("WITH v AS (INSERT INTO versions (station_id, number, set_id, source, "
                   "stored_at, note, serial_number, restored_from, pending_download, user_name, "
                   "host_name, simulated_ms) "
                   "SELECT $1::int8, coalesce(max(number), 0) + 1, $2::int8, $3::int2, "
                   "to_timestamp($4::float8 / 1000), $5::text, $6::text, $7::int8, $8::bool, "
                   "$9::text, $10::text, $11::int8 "
                   "FROM versions WHERE station_id = $1::int8 RETURNING id) "
                   "SELECT id, pg_notify('rs4sim_versions', current_schema() || ' ' || id) "
                   "FROM v",
                   p, "insert version"));
  return r.int64(0, 0);
}

Result<void> PgArchive::make_current(std::int64_t station, VersionId version) {
  Params p;
  p.add(station).add(version);
  BOOST_OUTCOME_TRY(c_->query("INSERT INTO current_versions (station_id, version_id) "
                              "VALUES ($1::int8, $2::int8) ON CONFLICT (station_id) "
                              "DO UPDATE SET version_id = excluded.version_id",
                              p, "set current version"));
  return success();
}

// A new current version supersedes a restore still waiting for its download.
Result<void> PgArchive::clear_pending(std::int64_t station) {
  Params p;
  p.add(station);
  BOOST_OUTCOME_TRY(c_->query("UPDATE versions SET pending_download = false "
                              "WHERE station_id = $1::int8 AND pending_download",
                              p, "clear pending download"));
  return success();
}

Result<VersionInfo> PgArchive::version_info(VersionId version) {
  Params p;
  p.add(version);
  const auto what = "version " + std::to_string(version);
  BOOST_OUTCOME_TRY(r, c_->query(version_query("WHERE v.id = $1::int8"), p, what));
  if (r.count() == 0) return archive_error(ArchiveError::kUnknownVersion, what);
  return read_version(r, 0);
}

Result<VersionWithSet> PgArchive::version_with_set(VersionId version) {
  Params p;
  p.add(version);
  const auto what = "version " + std::to_string(version);
  BOOST_OUTCOME_TRY(r, c_->query(version_query("WHERE v.id = $1::int8", true), p, what));
  if (r.count() == 0) return archive_error(ArchiveError::kUnknownVersion, what);
  return read_version_with_set(r, 0);
}

// One statement, so one snapshot and one round trip; the station is looked up apart only to
// tell an unknown station from one without a set.
Result<VersionWithSet> PgArchive::current(const StationKey& key) {
  return with_context("current", [&]() -> Result<VersionWithSet> {
    BOOST_OUTCOME_TRY(c_->reconnect_if_lost());
    Params p;
    p.add(key.bus).add(std::int64_t{key.address});
    BOOST_OUTCOME_TRY(
        r, c_->query(version_query("JOIN current_versions c ON c.version_id = v.id "
                                   "WHERE s.bus = $1::text AND s.address = $2::int2",
                                   true),
                     p, label(key)));
    if (r.count() == 1) return read_version_with_set(r, 0);
    BOOST_OUTCOME_TRY(station_id(key, false));
    return archive_error(ArchiveError::kNotFound, label(key) + " has no current set");
  });
}

Result<std::vector<VersionInfo>> PgArchive::history(const StationKey& key) {
  return with_context("history", [&]() -> Result<std::vector<VersionInfo>> {
    BOOST_OUTCOME_TRY(c_->reconnect_if_lost());
    Params p;
    p.add(key.bus).add(std::int64_t{key.address});
    BOOST_OUTCOME_TRY(
        r, c_->query(version_query("WHERE s.bus = $1::text AND s.address = $2::int2 "
                                   "ORDER BY v.number"),
                     p, label(key)));
    if (r.count() == 0) {
      BOOST_OUTCOME_TRY(station_id(key, false));  // unknown, or a station without sets
    }
    return read_versions(r);
  });
}

Result<VersionWithSet> PgArchive::get(VersionId version) {
  return with_context("get", [&]() -> Result<VersionWithSet> {
    BOOST_OUTCOME_TRY(c_->reconnect_if_lost());
    return version_with_set(version);  // one statement: one snapshot
  });
}

Result<std::optional<VersionId>> PgArchive::current_version(std::int64_t station) {
  Params p;
  p.add(station);
  BOOST_OUTCOME_TRY(r, c_->query("SELECT version_id FROM current_versions "
                                 "WHERE station_id = $1::int8",
                                 p, "read current version"));
  if (r.count() == 1) return std::optional<VersionId>(r.int64(0, 0));
  return std::optional<VersionId>();
}

Result<void> PgArchive::mark_downloaded(VersionId version) {
  return with_context("mark downloaded", [&]() -> Result<void> {
    return write<void>([&]() -> Result<void> {
      Params p;
      p.add(version);
      const auto what = "version " + std::to_string(version);
      BOOST_OUTCOME_TRY(
          r, c_->query("UPDATE versions SET pending_download = false WHERE id = $1::int8", p, what));
      if (r.affected() == 0) return archive_error(ArchiveError::kUnknownVersion, what);
      return success();
    });
  });
}

Result<VersionInfo> PgArchive::annotate(VersionId version, std::string note) {
  return with_context("note on version " + std::to_string(version), [&]() -> Result<VersionInfo> {
    BOOST_OUTCOME_TRY(check_note(note));
    return write<VersionInfo>([&]() -> Result<VersionInfo> {
      Params p;
      p.add(note).add(version);
      const auto what = "version " + std::to_string(version);
      BOOST_OUTCOME_TRY(
          r, c_->query("UPDATE versions SET note = $1::text WHERE id = $2::int8", p, what));
      if (r.affected() == 0) return archive_error(ArchiveError::kUnknownVersion, what);
      return version_info(version);
    });
  });
}

Result<std::vector<VersionInfo>> PgArchive::versions_after(VersionId after, std::size_t limit) {
  return with_context("versions after " + std::to_string(after),
                      [&]() -> Result<std::vector<VersionInfo>> {
    BOOST_OUTCOME_TRY(c_->reconnect_if_lost());
    Params p;
    p.add(after).add(static_cast<std::int64_t>(std::min<std::size_t>(limit, INT64_MAX)));
    BOOST_OUTCOME_TRY(
        r, c_->query(version_query("WHERE v.id > $1::int8 ORDER BY v.id LIMIT $2::int8"), p,
                     "read versions"));
    return read_versions(r);
  });
}

Result<VersionId> PgArchive::newest_version_id() {
  return with_context("newest version", [&]() -> Result<VersionId> {
    BOOST_OUTCOME_TRY(c_->reconnect_if_lost());
    BOOST_OUTCOME_TRY(r, c_->query("SELECT coalesce(max(id), 0)::int8 FROM versions", "read"));
    return r.int64(0, 0);
  });
}

// The given versions that exist, ascending by id (the change feed's notified ids).
Result<std::vector<VersionInfo>> PgArchive::versions_by_id(std::span<const VersionId> ids) {
  std::string list = "{";
  for (const auto id : ids) list += (list.size() > 1 ? "," : "") + std::to_string(id);
  list += "}";
  Params p;
  p.add(list);
  BOOST_OUTCOME_TRY(r, c_->query(version_query("WHERE v.id = ANY($1::int8[]) ORDER BY v.id"), p,
                                 "read versions"));
  return read_versions(r);
}

Result<std::vector<std::pair<std::int64_t, StationInfo>>> PgArchive::list_stations() {
  BOOST_OUTCOME_TRY(
      r, c_->query("SELECT s.id, s.bus, s.address, s.device_type, c.version_id, s.site, s.line "
                   "FROM stations s "
                   "LEFT JOIN current_versions c ON c.station_id = s.id "
                   "ORDER BY s.bus COLLATE \"C\", s.address",
                   "list"));
  std::vector<std::pair<std::int64_t, StationInfo>> out;
  std::unordered_map<std::int64_t, std::size_t> index;
  for (int i = 0; i < r.count(); ++i) {
    StationInfo info;
    info.key = StationKey{r.text(i, 1), static_cast<std::uint8_t>(r.int64(i, 2))};
    info.device_type = r.text(i, 3);
    if (!r.is_null(i, 4)) info.current = r.int64(i, 4);
    info.site = r.text(i, 5);
    info.line = r.text(i, 6);
    index[r.int64(i, 0)] = out.size();
    out.emplace_back(r.int64(i, 0), std::move(info));
  }
  BOOST_OUTCOME_TRY(
      s, c_->query("SELECT station_id, serial_number, "
                   "(extract(epoch FROM first_seen) * 1000)::int8, "
                   "(extract(epoch FROM last_seen) * 1000)::int8 FROM station_serials "
                   "ORDER BY station_id, first_seen, serial_number COLLATE \"C\"",
                   "serial numbers"));
  for (int i = 0; i < s.count(); ++i) {
    const auto it = index.find(s.int64(i, 0));
    if (it == index.end()) continue;
    out[it->second].second.serials.push_back(
        {s.text(i, 1), from_ms(s.int64(i, 2)), from_ms(s.int64(i, 3))});
  }
  return out;
}

Result<void> PgArchive::save_proxy_state(const StationKey& station,
                                         std::span<const std::uint8_t> state, Timestamp at) {
  return with_context("save proxy state of " + label(station), [&]() -> Result<void> {
    BOOST_OUTCOME_TRY(check_proxy_state(station, state));
    return write<void>([&]() -> Result<void> {
      Params p;
      p.add(station.bus).add(std::int64_t{station.address}).add(state).add(to_ms(at));
      BOOST_OUTCOME_TRY(c_->query(
          "INSERT INTO proxy_state (bus, address, state, saved_at) VALUES ($1::text, $2::int2, "
          "$3::bytea, to_timestamp($4::float8 / 1000)) ON CONFLICT (bus, address) DO UPDATE "
          "SET state = excluded.state, saved_at = excluded.saved_at",
          p, label(station)));
      return success();
    });
  });
}

Result<std::vector<std::uint8_t>> PgArchive::load_proxy_state(const StationKey& station) {
  return with_context("load proxy state of " + label(station),
                      [&]() -> Result<std::vector<std::uint8_t>> {
                        BOOST_OUTCOME_TRY(c_->reconnect_if_lost());
                        Params p;
                        p.add(station.bus).add(std::int64_t{station.address});
                        BOOST_OUTCOME_TRY(r, c_->query("SELECT state FROM proxy_state WHERE "
                                                       "bus = $1::text AND address = $2::int2",
                                                       p, label(station)));
                        if (r.count() == 0) {
                          return archive_error(ArchiveError::kNotFound,
                                               label(station) + " has no saved proxy state");
                        }
                        return r.bytes(0, 0);
                      });
}

}  // namespace rs4sim::storage
