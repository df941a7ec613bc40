// Every operation of SqliteArchive on a real file (integration: SQLite on disk).
#include "storage/sqlite_archive.h"

#include "tests/storage/archive_test_support.h"

#include <gtest/gtest.h>

namespace rs4sim::storage {
namespace {

using testing::at_ms;
using testing::make_blob;
using testing::request;

const StationKey kStation{"bus1", 4};
const StationKey kOther{"bus1", 5};

class SqliteArchiveTest : public ::testing::Test {
 protected:
  void SetUp() override { archive_ = SqliteArchive::open(path_).value(); }
  testing::TempDir dir_;
  std::filesystem::path path_ = dir_.file("archive.sqlite3");
  std::unique_ptr<SqliteArchive> archive_;
};

TEST_F(SqliteArchiveTest, StoreMakesANewCurrentVersion) {
  const auto blob = make_blob(1);
  auto r = request(kStation, blob);
  r.note = "first";
  const auto v = archive_->store(r).value();
  EXPECT_EQ(v.number, 1u);
  EXPECT_EQ(v.station, kStation);
  EXPECT_EQ(v.crc32, crc32(blob));
  EXPECT_EQ(v.size, blob.size());
  EXPECT_EQ(v.source, VersionSource::kUpload);
  EXPECT_EQ(v.at, at_ms(1'700'000'000'000));
  EXPECT_EQ(v.note, "first");
  EXPECT_EQ(v.serial_number, "SN-1");
  EXPECT_FALSE(v.pending_download);
  EXPECT_FALSE(v.restored_from);

  const auto cur = archive_->current(kStation).value();
  EXPECT_EQ(cur.version, v);
  EXPECT_EQ(cur.set.blob, blob);
  EXPECT_EQ(cur.set.summary, "{\"test\":true}");

  const auto v2 = archive_->store(request(kStation, make_blob(2), 1'700'000'001'000)).value();
  EXPECT_EQ(v2.number, 2u);
  EXPECT_EQ(archive_->current(kStation).value().version.id, v2.id);
}

TEST_F(SqliteArchiveTest, VersionNumbersArePerStation) {
  archive_->store(request(kStation, make_blob(1))).value();
  archive_->store(request(kStation, make_blob(2))).value();
  const auto other = archive_->store(request(kOther, make_blob(3))).value();
  EXPECT_EQ(other.number, 1u);
}

TEST_F(SqliteArchiveTest, SameBytesShareOneSet) {
  const auto blob = make_blob(7);
  const auto a = archive_->store(request(kStation, blob)).value();
  const auto b = archive_->store(request(kOther, blob)).value();
  const auto c = archive_->store(request(kStation, make_blob(8))).value();
  EXPECT_EQ(a.set_id, b.set_id);
  EXPECT_NE(a.set_id, c.set_id);
  EXPECT_NE(a.id, b.id);
  const auto snap = archive_->export_snapshot(at_ms(0)).value();
  EXPECT_EQ(snap.sets.size(), 2u);
}

TEST_F(SqliteArchiveTest, HistoryAndGet) {
  std::vector<VersionInfo> stored;
  for (std::uint64_t i = 0; i < 5; ++i) {
    stored.push_back(archive_->store(request(kStation, make_blob(i))).value());
  }
  archive_->store(request(kOther, make_blob(99))).value();
  const auto history = archive_->history(kStation).value();
  EXPECT_EQ(history, stored);
  const auto third = archive_->get(stored[2].id).value();
  EXPECT_EQ(third.version, stored[2]);
  EXPECT_EQ(third.set.blob, make_blob(2));
}

TEST_F(SqliteArchiveTest, RestoreIsANewCurrentVersionPendingDownload) {
  const auto v1 = archive_->store(request(kStation, make_blob(1))).value();
  archive_->store(request(kStation, make_blob(2))).value();
  const auto r = archive_->restore(v1.id, at_ms(42), "back to 1").value();
  EXPECT_EQ(r.number, 3u);
  EXPECT_EQ(r.source, VersionSource::kRestore);
  EXPECT_EQ(r.set_id, v1.set_id);
  EXPECT_EQ(r.restored_from, v1.id);
  EXPECT_TRUE(r.pending_download);
  EXPECT_EQ(r.at, at_ms(42));
  EXPECT_EQ(r.note, "back to 1");
  const auto cur = archive_->current(kStation).value();
  EXPECT_EQ(cur.version.id, r.id);
  EXPECT_EQ(cur.set.blob, make_blob(1));

  archive_->mark_downloaded(r.id).value();
  EXPECT_FALSE(archive_->current(kStation).value().version.pending_download);
}

TEST_F(SqliteArchiveTest, ANewStoreSupersedesAPendingRestore) {
  const auto v1 = archive_->store(request(kStation, make_blob(1))).value();
  const auto r = archive_->restore(v1.id, at_ms(2), "").value();
  archive_->store(request(kStation, make_blob(3))).value();
  EXPECT_FALSE(archive_->get(r.id).value().version.pending_download);
}

TEST_F(SqliteArchiveTest, StationsWithSerialNumbersSeen) {
  const auto first = make_blob(1);
  const auto second = make_blob(2);
  auto r = request(kStation, first, 1000);
  r.serial_number = "A";
  archive_->store(r).value();
  r.blob = second;
  r.crc32 = crc32(r.blob);
  r.at = at_ms(2000);
  archive_->store(r).value();
  r.serial_number = "B";
  r.device_type = "TEST-DEVICE-2";
  r.at = at_ms(3000);
  const auto last = archive_->store(r).value();
  archive_
      ->log_sync({kOther, at_ms(5), "power-up check", SyncDirection::kNone, SyncOutcome::kFailed,
                  0x2B09, 0, 0, std::chrono::milliseconds{10}})
      .value();

  const auto list = archive_->stations().value();
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0].key, kStation);
  EXPECT_EQ(list[0].device_type, "TEST-DEVICE-2");
  EXPECT_EQ(list[0].current, last.id);
  ASSERT_EQ(list[0].serials.size(), 2u);
  EXPECT_EQ(list[0].serials[0], (SerialSeen{"A", at_ms(1000), at_ms(2000)}));
  EXPECT_EQ(list[0].serials[1], (SerialSeen{"B", at_ms(3000), at_ms(3000)}));
  EXPECT_EQ(list[1].key, kOther);  // created by the sync log, no set yet
  EXPECT_FALSE(list[1].current);
}

TEST_F(SqliteArchiveTest, SyncLogKeepsTheNewestEntriesOldestFirst) {
  for (int i = 0; i < 5; ++i) {
    archive_
        ->log_sync({kStation, at_ms(i), "reason " + std::to_string(i), SyncDirection::kUpload,
                    SyncOutcome::kSucceeded, 0, 0, static_cast<std::uint32_t>(i),
                    std::chrono::milliseconds{i * 100}})
        .value();
  }
  const auto all = archive_->sync_log(kStation, 100).value();
  ASSERT_EQ(all.size(), 5u);
  EXPECT_EQ(all[0].reason, "reason 0");
  EXPECT_EQ(all[4].error_number_device, 4u);
  EXPECT_EQ(all[4].duration, std::chrono::milliseconds{400});
  const auto last2 = archive_->sync_log(kStation, 2).value();
  ASSERT_EQ(last2.size(), 2u);
  EXPECT_EQ(last2[0], all[3]);
  EXPECT_EQ(last2[1], all[4]);
}

TEST_F(SqliteArchiveTest, IntegrityCheckPassesAndFindsABadBlob) {
  archive_->store(request(kStation, make_blob(1))).value();
  EXPECT_TRUE(archive_->check_integrity().value().ok());
  {  // damage a blob behind the archive's back
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(path_.c_str(), &db), SQLITE_OK);
    ASSERT_EQ(sqlite3_exec(db, "UPDATE parameter_sets SET blob = x'00'", nullptr, nullptr, nullptr),
              SQLITE_OK);
    sqlite3_close(db);
  }
  const auto report = archive_->check_integrity().value();
  ASSERT_EQ(report.problems.size(), 2u);
  EXPECT_EQ(report.problems[0], "parameter set 1: CRC-32 does not match its blob");
  EXPECT_EQ(report.problems[1], "parameter set 1: size does not match its blob");
}

TEST_F(SqliteArchiveTest, ReopenKeepsEverything) {
  const auto v = archive_->store(request(kStation, make_blob(1))).value();
  archive_.reset();
  auto again = SqliteArchive::open(path_).value();
  EXPECT_EQ(again->current(kStation).value().version, v);
}

TEST_F(SqliteArchiveTest, InMemoryArchive) {
  auto mem = SqliteArchive::open(":memory:").value();
  mem->store(request(kStation, make_blob(1))).value();
  EXPECT_EQ(mem->history(kStation).value().size(), 1u);
}

TEST_F(SqliteArchiveTest, CreatesTheParentDirectory) {
  const auto deep = dir_.file("a/b/archive.sqlite3");
  auto a = SqliteArchive::open(deep).value();
  EXPECT_TRUE(std::filesystem::exists(deep));
}

}  // namespace
}  // namespace rs4sim::storage

namespace rs4sim::storage {
namespace {

class ProxyStateTest : public ::testing::Test {
 protected:
  void SetUp() override { archive_ = SqliteArchive::open(path_).value(); }
  testing::TempDir dir_;
  std::filesystem::path path_ = dir_.file("archive.sqlite3");
  std::unique_ptr<SqliteArchive> archive_;
};

TEST_F(ProxyStateTest, SavedStateSurvivesReopenAndIsReplaced) {
  const StationKey station{"bus1", 4};
  EXPECT_EQ(archive_->load_proxy_state(station).error().code, ArchiveError::kNotFound);
  const std::vector<std::uint8_t> first{0x01, 0x02, 0x03};
  archive_->save_proxy_state(station, first, testing::at_ms(1000)).value();
  const std::vector<std::uint8_t> second(34, 0xA5);  // the FB's 34 retentive bytes
  archive_->save_proxy_state(station, second, testing::at_ms(2000)).value();
  archive_.reset();
  archive_ = SqliteArchive::open(path_).value();
  EXPECT_EQ(archive_->load_proxy_state(station).value(), second);
  // Per address and bus; no station row is needed, none is created.
  EXPECT_EQ(archive_->load_proxy_state({"bus1", 5}).error().code, ArchiveError::kNotFound);
  EXPECT_EQ(archive_->load_proxy_state({"bus2", 4}).error().code, ArchiveError::kNotFound);
  EXPECT_TRUE(archive_->stations().value().empty());
  EXPECT_TRUE(archive_->check_integrity().value().ok());
}

TEST_F(ProxyStateTest, BadStateIsRefusedAndNothingChanges) {
  const StationKey station{"bus1", 4};
  const std::vector<std::uint8_t> kept{0x07};
  archive_->save_proxy_state(station, kept, testing::at_ms(1)).value();
  const std::vector<std::uint8_t> too_big(kMaxProxyStateSize + 1, 0);
  const auto big = archive_->save_proxy_state(station, too_big, testing::at_ms(2));
  ASSERT_TRUE(big.has_error());
  EXPECT_EQ(big.error().code, ArchiveError::kInvalidArgument);
  EXPECT_NE(big.error().message.find("257 bytes"), std::string::npos) << big.error().message;
  EXPECT_EQ(archive_->save_proxy_state(station, {}, testing::at_ms(2)).error().code,
            ArchiveError::kInvalidArgument);
  EXPECT_EQ(archive_->save_proxy_state({"bus1", 127}, kept, testing::at_ms(2)).error().code,
            ArchiveError::kInvalidArgument);
  EXPECT_EQ(archive_->load_proxy_state(station).value(), kept);
}

}  // namespace
}  // namespace rs4sim::storage
