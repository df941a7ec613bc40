#pragma once
// What SqliteArchive and PgArchive do alike, written once over the rows each engine reads and
// writes: store, restore, export and import (docs/storage.md "Import"). An engine supplies its
// transactions and the row operations below; the meaning of a call lives here.

#include "storage/parameter_archive.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace rs4sim::storage {

class RowArchive : public ParameterArchive {
 public:
  Result<VersionInfo> store(const StoreRequest& request) override;
  using ParameterArchive::restore;
  Result<VersionInfo> restore(VersionId version, Timestamp at, std::string note,
                              const Author& by) override;
  Result<Snapshot> export_snapshot(Timestamp exported_at) override;
  Result<std::vector<StationInfo>> stations() override;
  Result<void> log_sync(const SyncLogEntry& entry) override;
  Result<std::vector<SyncLogEntry>> sync_log(const StationKey& station, std::size_t limit) override;
  Result<ImportSummary> import_snapshot(const Snapshot& snapshot,
                                        const ImportOptions& options) override;
  using ParameterArchive::import_snapshot;

 protected:
  struct NewVersion {
    SetId set_id{0};
    VersionSource source{VersionSource::kUpload};
    Timestamp at{};
    std::optional<std::chrono::milliseconds> simulated;
    std::string_view note;
    std::string_view serial_number;
    std::string_view user;
    std::string_view host;
    std::optional<VersionId> restored_from;
    bool pending_download{false};
  };
  using Body = std::function<Result<void>()>;

  RowArchive() = default;

  // `body` in one write transaction, committed when it succeeds (PostgreSQL: again when it
  // lost a serialization race); in one read transaction (one snapshot for all its reads).
  virtual Result<void> in_write(const Body& body) = 0;
  virtual Result<void> in_read(const Body& body) = 0;

  // The row operations, each inside the caller's transaction.
  virtual Result<std::int64_t> lock_station(const StationKey& key) = 0;  // kUnknownStation
  virtual Result<std::int64_t> find_station(const StationKey& key) = 0;  // the same, no lock
  // Creates the station or locks its row; a non-empty device type, site or line replaces the
  // stored one.
  virtual Result<std::int64_t> upsert_station(const StationKey& key, std::string_view device_type,
                                              std::string_view site, std::string_view line) = 0;
  virtual Result<void> see_serial(std::int64_t station, std::string_view serial, Timestamp first,
                                  Timestamp last) = 0;
  // The id of the set with exactly these bytes, inserted if new (`inserted` tells).
  virtual Result<SetId> intern_set(std::span<const std::uint8_t> blob, std::uint32_t crc,
                                   std::string_view summary, bool& inserted) = 0;
  virtual Result<VersionId> append_version(std::int64_t station, const NewVersion& v) = 0;
  virtual Result<void> make_current(std::int64_t station, VersionId version) = 0;
  // A new current version supersedes a restore still waiting for its download.
  virtual Result<void> clear_pending(std::int64_t station) = 0;
  virtual Result<std::optional<VersionId>> current_version(std::int64_t station) = 0;
  virtual Result<VersionInfo> version_info(VersionId version) = 0;  // kUnknownVersion
  virtual Result<std::vector<VersionInfo>> station_versions(std::int64_t station) = 0;
  // Every station with its row id, ordered by bus and address.
  virtual Result<std::vector<std::pair<std::int64_t, StationInfo>>> list_stations() = 0;
  virtual Result<std::vector<ParameterSetRecord>> all_sets() = 0;
  virtual Result<std::vector<SyncLogEntry>> sync_rows(std::int64_t station, const StationKey& key,
                                                      std::int64_t limit) = 0;
  virtual Result<void> insert_sync(std::int64_t station, const SyncLogEntry& entry) = 0;

  // `body`'s value out of in_write()/in_read().
  template <class T, class F>
  Result<T> written(F&& body) {
    return value_of<T>(true, std::forward<F>(body));
  }
  template <class T, class F>
  Result<T> read_in_one(F&& body) {
    return value_of<T>(false, std::forward<F>(body));
  }

 private:
  template <class T, class F>
  Result<T> value_of(bool write, F&& body) {
    std::optional<T> out;
    const Body run = [&]() -> Result<void> {
      auto r = body();
      if (!r) return std::move(r).error();
      out = std::move(r).value();
      return boost::outcome_v2::success();
    };
    auto done = write ? in_write(run) : in_read(run);
    if (!done) return std::move(done).error();
    return std::move(*out);
  }

  Result<VersionInfo> store_rows(const StoreRequest& r);
  Result<SnapshotStation> export_station(std::int64_t id, StationInfo info);
  struct ImportContext {
    const ImportOptions& options;
    std::unordered_map<SetId, SetId> set_ids;  // the file's set id -> the archive's
  };
  Result<ImportedStation> import_station(const SnapshotStation& station,
                                         const ImportContext& context);
  Result<std::optional<std::uint32_t>> adopt_current(std::int64_t station,
                                                     const SnapshotStation& in,
                                                     const ImportContext& context,
                                                     ImportedStation& out);
  Result<std::size_t> import_sync_log(std::int64_t station, const SnapshotStation& in);
};

}  // namespace rs4sim::storage
