// Import on every engine (docs/storage.md "Import"): a version already there is recognised,
// the history grows without moving the present unless asked, never over a newer restore
// still pending download, and the summary says what happened.
#include "storage/archive_file.h"
#include "storage/sqlite_archive.h"

#include "tests/storage/archive_engines.h"
#include "tests/storage/archive_test_support.h"

#include <gtest/gtest.h>

namespace rs4sim::storage {
namespace {

using testing::request;  // request(station, blob, at ms)
using testing::make_blob;
using testing::at_ms;

const StationKey kStation{"line1", 7};

class ArchiveImport : public testing::EngineTest {
 protected:
  // A backup from another archive: one version of kStation with blob `n`, written at `at`.
  static Snapshot foreign_backup(std::uint8_t n, std::int64_t at) {
    auto other = SqliteArchive::open(":memory:").value();
    other->store(request(kStation, make_blob(n), at)).value();
    return other->export_snapshot(at_ms(at + 1)).value();
  }
  std::uint32_t current_number() {
    return archive_->current(kStation).value().version.number;
  }
};
using testing::engine_name;

INSTANTIATE_TEST_SUITE_P(Engines, ArchiveImport, ::testing::Values("sqlite", "postgresql"),
                         engine_name);

// Issue: the same backup imported twice gave four versions and six sync-log rows.
TEST_P(ArchiveImport, TheSameBackupTwiceAddsNothingTheSecondTime) {
  const auto v1 = archive_->store(request(kStation, make_blob(1), 1000)).value();
  archive_->store(request(kStation, make_blob(2), 2000)).value();
  archive_->restore(v1.id, at_ms(3000), "back to 1").value();
  archive_
      ->log_sync({kStation, at_ms(4000), "pc-adapter-removed", SyncDirection::kDownload,
                  SyncOutcome::kSucceeded, 0, 0, 0, std::chrono::milliseconds{42}})
      .value();
  const auto backup = export_binary(*archive_, at_ms(9000)).value();
  const auto before = engine_->digest();
  for (int round = 0; round < 2; ++round) {
    const auto summary = import_binary(*archive_, backup).value();
    EXPECT_EQ(summary.versions, 0u);
    EXPECT_EQ(summary.versions_present, 3u);
    EXPECT_EQ(summary.sync_log_entries, 0u);
    EXPECT_EQ(summary.sync_log_present, 1u);
    EXPECT_EQ(summary.new_sets, 0u);
    ASSERT_EQ(summary.per_station.size(), 1u);
    EXPECT_EQ(summary.per_station[0].current, ImportCurrent::kUnchanged);
    EXPECT_EQ(summary.per_station[0].current_number, 3u);
  }
  EXPECT_EQ(engine_->digest(), before);
  EXPECT_EQ(archive_->history(kStation).value().size(), 3u);
  EXPECT_EQ(archive_->sync_log(kStation, 100).value().size(), 1u);
}

TEST_P(ArchiveImport, AnOlderBackupAppendsHistoryAndLeavesTheCurrentSet) {
  archive_->store(request(kStation, make_blob(2), 2000)).value();
  const auto summary = archive_->import_snapshot(foreign_backup(3, 1500)).value();
  EXPECT_EQ(summary.versions, 1u);
  EXPECT_EQ(summary.per_station[0].current, ImportCurrent::kUnchanged);
  const auto history = archive_->history(kStation).value();
  ASSERT_EQ(history.size(), 2u);
  EXPECT_FALSE(history[1].pending_download);
  EXPECT_EQ(archive_->current(kStation).value().set.blob, make_blob(2));
  EXPECT_EQ(current_number(), 1u);
}

TEST_P(ArchiveImport, MakeCurrentMovesThePresentOnlyWhenAsked) {
  archive_->store(request(kStation, make_blob(2), 2000)).value();
  const auto summary =
      archive_->import_snapshot(foreign_backup(3, 1500), ImportOptions{true}).value();
  EXPECT_EQ(summary.per_station[0].current, ImportCurrent::kMadeCurrent);
  EXPECT_EQ(summary.per_station[0].current_number, 2u);
  EXPECT_EQ(archive_->current(kStation).value().set.blob, make_blob(3));
}

// Issue (PostgreSQL): an older backup made an old version current over a newer pending
// restore, which stayed "pending download" without being current.
TEST_P(ArchiveImport, MakeCurrentNeverGoesOverANewerPendingRestore) {
  const auto v1 = archive_->store(request(kStation, make_blob(1), 1000)).value();
  archive_->store(request(kStation, make_blob(2), 2000)).value();
  const auto pending = archive_->restore(v1.id, at_ms(3000), "back to 1").value();
  const auto summary =
      archive_->import_snapshot(foreign_backup(3, 1500), ImportOptions{true}).value();
  EXPECT_EQ(summary.per_station[0].current, ImportCurrent::kKeptPending);
  EXPECT_EQ(summary.versions, 1u);
  const auto current = archive_->current(kStation).value().version;
  EXPECT_EQ(current.id, pending.id);
  EXPECT_TRUE(current.pending_download);
  const auto history = archive_->history(kStation).value();
  for (const auto& v : history) {
    EXPECT_EQ(v.pending_download, v.id == pending.id) << "version " << v.number;
  }
}

// A newer version of the file does supersede the pending restore when asked (as a new store
// would); the restore is no longer pending.
TEST_P(ArchiveImport, MakeCurrentWithANewerVersionSupersedesThePendingRestore) {
  const auto v1 = archive_->store(request(kStation, make_blob(1), 1000)).value();
  const auto pending = archive_->restore(v1.id, at_ms(3000), "back to 1").value();
  archive_->import_snapshot(foreign_backup(3, 5000), ImportOptions{true}).value();
  EXPECT_EQ(archive_->current(kStation).value().set.blob, make_blob(3));
  EXPECT_FALSE(archive_->get(pending.id).value().version.pending_download);
}

TEST_P(ArchiveImport, AStationNewToTheArchiveTakesTheFilesCurrentVersion) {
  const auto summary = archive_->import_snapshot(foreign_backup(3, 1500)).value();
  EXPECT_EQ(summary.per_station[0].current, ImportCurrent::kMadeCurrent);
  EXPECT_EQ(archive_->current(kStation).value().set.blob, make_blob(3));
}

}  // namespace
}  // namespace rs4sim::storage
