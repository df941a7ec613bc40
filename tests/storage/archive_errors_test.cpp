// The error paths only SQLite has (locks, read-only and full files, foreign files, migrations
// of a file): the specific code, a message naming the object, and the archive file unchanged
// afterwards (digest before == digest after). The errors every engine shares are in
// archive_contract_test.cpp.
#include "storage/archive_file.h"
#include "storage/sqlite_archive.h"
#include "tests/storage/archive_test_support.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

namespace rs4sim::storage {
namespace {

using testing::at_ms;
using testing::digest;
using ::testing::HasSubstr;
using testing::make_blob;
using testing::request;

const StationKey kStation{"bus1", 4};

void raw_exec(const std::filesystem::path& file, const char* sql) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(file.c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db, sql, nullptr, nullptr, nullptr), SQLITE_OK) << sqlite3_errmsg(db);
  sqlite3_close(db);
}

class ArchiveErrorsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    archive_ = SqliteArchive::open(path_).value();
    first_ = archive_->store(request(kStation, make_blob(1))).value();
    archive_
        ->log_sync({kStation, at_ms(1), "r", SyncDirection::kVerify, SyncOutcome::kSucceeded, 0, 0,
                    0, std::chrono::milliseconds{1}})
        .value();
    before_ = digest(path_);
  }
  // The error has `code`, its message contains `text`, and the file is unchanged.
  template <class T>
  void expect_error(const Result<T>& r, ArchiveError code, const std::string& text) {
    ASSERT_TRUE(r.has_error());
    EXPECT_EQ(r.error().code, code) << r.error().message;
    EXPECT_THAT(r.error().message, HasSubstr(text));
    EXPECT_EQ(digest(path_), before_);
  }
  testing::TempDir dir_;
  std::filesystem::path path_ = dir_.file("archive.sqlite3");
  std::unique_ptr<SqliteArchive> archive_;
  VersionInfo first_;
  std::string before_;
};

TEST_F(ArchiveErrorsTest, LockedByAnotherWriter) {
  archive_.reset();
  SqliteOptions options;
  options.busy_timeout = std::chrono::milliseconds{50};
  archive_ = SqliteArchive::open(path_, options).value();
  sqlite3* other = nullptr;
  ASSERT_EQ(sqlite3_open(path_.c_str(), &other), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(other, "BEGIN IMMEDIATE", nullptr, nullptr, nullptr), SQLITE_OK);
  const auto r = archive_->store(request(kStation, make_blob(2)));
  const auto restore = archive_->restore(first_.id, at_ms(5), "");
  sqlite3_exec(other, "ROLLBACK", nullptr, nullptr, nullptr);
  sqlite3_close(other);
  expect_error(r, ArchiveError::kBusy,
               "store station bus1/4: BEGIN IMMEDIATE: archive locked by another writer");
  expect_error(restore, ArchiveError::kBusy, "restore");
  EXPECT_TRUE(archive_->current(kStation).has_value());  // reads still work
}

TEST_F(ArchiveErrorsTest, OpenedReadOnly) {
  archive_.reset();
  SqliteOptions options;
  options.read_only = true;
  archive_ = SqliteArchive::open(path_, options).value();
  EXPECT_EQ(archive_->current(kStation).value().version, first_);
  expect_error(archive_->store(request(kStation, make_blob(2))), ArchiveError::kReadOnly,
               "store station bus1/4");
  expect_error(
      archive_->log_sync(
          {kStation, at_ms(1), "r", SyncDirection::kNone, SyncOutcome::kFailed, 0, 0, 0, {}}),
      ArchiveError::kReadOnly, "log sync station bus1/4");
}

TEST_F(ArchiveErrorsTest, ReadOnlyFile) {
  if (::geteuid() == 0) GTEST_SKIP() << "root ignores file permissions";
  archive_.reset();
  std::filesystem::permissions(
      path_, std::filesystem::perms::owner_read | std::filesystem::perms::group_read);
  auto ro = SqliteArchive::open(path_);
  if (ro) {
    expect_error(ro.value()->store(request(kStation, make_blob(2))), ArchiveError::kReadOnly,
                 "store");
  } else {
    expect_error(ro, ArchiveError::kReadOnly, path_.string());
  }
}

TEST_F(ArchiveErrorsTest, DiskFull) {
  archive_.reset();
  SqliteOptions options;
  options.max_page_count = 40;  // 160 KiB of 4 KiB pages
  archive_ = SqliteArchive::open(path_, options).value();
  Result<VersionInfo> r = first_;
  std::uint64_t seed = 100;
  while (r.has_value()) {
    before_ = digest(path_);
    r = archive_->store(request(kStation, make_blob(seed++)));
  }
  expect_error(r, ArchiveError::kDiskFull, "store station bus1/4: insert parameter set: disk full");
  EXPECT_TRUE(archive_->check_integrity().value().ok());
}

TEST_F(ArchiveErrorsTest, NotAnSqliteFile) {
  archive_.reset();
  const auto file = dir_.file("notes.txt");
  std::ofstream(file) << std::string(5000, 'x');
  const auto r = SqliteArchive::open(file);
  ASSERT_TRUE(r.has_error());
  EXPECT_EQ(r.error().code, ArchiveError::kNotAnArchive);
  EXPECT_THAT(r.error().message, HasSubstr(file.string()));
  EXPECT_EQ(std::filesystem::file_size(file), 5000u);
}

TEST_F(ArchiveErrorsTest, SqliteFileOfSomeoneElse) {
  archive_.reset();
  const auto file = dir_.file("other.db");
  raw_exec(file, "CREATE TABLE t (x); INSERT INTO t VALUES (1);");
  const auto before = digest(file);
  const auto r = SqliteArchive::open(file);
  ASSERT_TRUE(r.has_error());
  EXPECT_EQ(r.error().code, ArchiveError::kNotAnArchive);
  EXPECT_THAT(r.error().message, HasSubstr("a SQLite database with other tables"));
  EXPECT_EQ(digest(file), before);

  raw_exec(file, "PRAGMA application_id = 1234;");
  const auto r2 = SqliteArchive::open(file);
  ASSERT_TRUE(r2.has_error());
  EXPECT_EQ(r2.error().code, ArchiveError::kNotAnArchive);
  EXPECT_THAT(r2.error().message, HasSubstr("application_id 1234 is not rs4sim's"));
}

TEST_F(ArchiveErrorsTest, NewerSchema) {
  archive_.reset();
  raw_exec(path_, "PRAGMA user_version = 99;");
  before_ = digest(path_);
  expect_error(SqliteArchive::open(path_), ArchiveError::kNewerSchema,
               "schema version 99, this rs4sim knows up to 5");
}

TEST_F(ArchiveErrorsTest, ImportOfACorruptFile) {
  const std::vector<std::uint8_t> garbage{0xFF, 0xFF, 0xFF};
  expect_error(import_binary(*archive_, garbage), ArchiveError::kCorruptImport,
               "import: not a binary rs4sim.v1.ArchiveExport");
  expect_error(import_json(*archive_, "{\"formatVersion\": 1, \"bogus\": 2}"),
               ArchiveError::kCorruptImport, "import: not a JSON rs4sim.v1.ArchiveExport");
  expect_error(import_json(*archive_, "{\"formatVersion\": 2}"), ArchiveError::kCorruptImport,
               "format version 2, this rs4sim reads 1");
}

TEST_F(ArchiveErrorsTest, ImportThatFailsMidWriteRollsBack) {
  // 30 distinct sets need ~90 pages: the disk fills part-way through the transaction.
  Snapshot snap;
  SnapshotStation st;
  st.key = {"bus2", 3};
  for (std::uint32_t i = 1; i <= 30; ++i) {
    const auto blob = make_blob(1000 + i);
    snap.sets.push_back({i, crc32(blob), blob, ""});
    st.versions.push_back({i, i, at_ms(i), VersionSource::kUpload, "", 0, false, "", "", "", {}});
  }
  st.current_version = 30;
  snap.stations.push_back(st);
  archive_.reset();
  SqliteOptions options;
  options.max_page_count = 40;
  archive_ = SqliteArchive::open(path_, options).value();
  expect_error(archive_->import_snapshot(snap), ArchiveError::kDiskFull,
               "import: insert parameter set: disk full");
}

TEST(ArchiveErrorValue, ThrowsSystemErrorWithTheMessage) {
  Result<int> r = archive_error(ArchiveError::kUnknownVersion, "version 3");
  try {
    (void)r.value();
    FAIL();
  } catch (const std::system_error& e) {
    EXPECT_EQ(e.code(), ArchiveError::kUnknownVersion);
    EXPECT_THAT(e.what(), HasSubstr("version 3: unknown version"));
  }
}

}  // namespace
}  // namespace rs4sim::storage
