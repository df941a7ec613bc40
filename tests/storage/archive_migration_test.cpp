// Forward migrations: files written by hand in older schemas open and are upgraded.
#include "storage/sqlite_archive.h"
#include "tests/storage/archive_test_support.h"
#include "tests/storage/old_schemas.h"

#include <gtest/gtest.h>

#include <fstream>

namespace rs4sim::storage {
namespace {

using testing::at_ms;

// Schema version 1 as rs4sim 0.1 wrote it (no pending_download, no sync_log), with one
// station, one set ("abc", CRC-32 0x352441C2) and one current version.
const std::string kSchemaV1File = std::string(testing::kSqliteSchema1Tables) + R"sql(
INSERT INTO stations VALUES (1, 'plant', 9, 'OLD-DEVICE');
INSERT INTO station_serials VALUES (1, 'S-9', 1000, 1000);
INSERT INTO parameter_sets VALUES (1, 891568578, 3, x'616263', 'abc summary');
INSERT INTO versions VALUES (1, 1, 1, 1, 1, 1000, 'from v1', 'S-9', NULL);
INSERT INTO current_versions VALUES (1, 1);
PRAGMA application_id = 1381184577;
PRAGMA user_version = 1;
)sql";

std::int64_t user_version(const std::filesystem::path& file) {
  sqlite3* db = nullptr;
  sqlite3_open(file.c_str(), &db);
  sqlite3_stmt* s = nullptr;
  sqlite3_prepare_v2(db, "PRAGMA user_version", -1, &s, nullptr);
  sqlite3_step(s);
  const auto v = sqlite3_column_int64(s, 0);
  sqlite3_finalize(s);
  sqlite3_close(db);
  return v;
}

void write_v1_file(const std::filesystem::path& file) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(file.c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db, kSchemaV1File.c_str(), nullptr, nullptr, nullptr), SQLITE_OK);
  sqlite3_close(db);
}

TEST(ArchiveMigration, Version1FileIsUpgradedAndKeepsItsRows) {
  testing::TempDir dir;
  const auto file = dir.file("v1.sqlite3");
  write_v1_file(file);
  ASSERT_EQ(user_version(file), 1);
  auto archive = SqliteArchive::open(file).value();
  EXPECT_EQ(user_version(file), 5);
  const StationKey station{"plant", 9};
  const auto cur = archive->current(station).value();
  EXPECT_EQ(cur.version.note, "from v1");
  EXPECT_EQ(cur.version.crc32, 0x352441C2u);
  EXPECT_FALSE(cur.version.pending_download);  // the new columns' defaults
  EXPECT_EQ(cur.version.user, "");
  EXPECT_EQ(cur.version.host, "");
  EXPECT_EQ(archive->stations().value().at(0).site, "");
  EXPECT_EQ(cur.set.blob, (std::vector<std::uint8_t>{'a', 'b', 'c'}));
  EXPECT_TRUE(archive->check_integrity().value().ok());
  // The version-2 features work on the upgraded file.
  archive
      ->log_sync(
          {station, at_ms(2000), "r", SyncDirection::kVerify, SyncOutcome::kSucceeded, 0, 0, 0, {}})
      .value();
  EXPECT_EQ(archive->sync_log(station, 10).value().size(), 1u);
  EXPECT_TRUE(archive->restore(cur.version.id, at_ms(3000), "").value().pending_download);
  // ... and the version-4 ones.
  const auto noted = archive->annotate(cur.version.id, "checked in v4").value();
  EXPECT_EQ(noted.note, "checked in v4");
}

TEST(ArchiveMigration, EmptyFileIsVersion0AndGetsTheWholeSchema) {
  testing::TempDir dir;
  const auto file = dir.file("empty.sqlite3");
  std::ofstream{file};  // 0 bytes: SQLite treats it as an empty database
  auto archive = SqliteArchive::open(file).value();
  EXPECT_EQ(user_version(file), 5);
  EXPECT_TRUE(archive->stations().value().empty());
}

TEST(ArchiveMigration, ReadOnlyOpenOfAnOldFileIsRefused) {
  testing::TempDir dir;
  const auto file = dir.file("v1.sqlite3");
  write_v1_file(file);
  SqliteOptions options;
  options.read_only = true;
  const auto r = SqliteArchive::open(file, options);
  ASSERT_TRUE(r.has_error());
  EXPECT_EQ(r.error().code, ArchiveError::kReadOnly);
  EXPECT_EQ(user_version(file), 1);
}

}  // namespace
}  // namespace rs4sim::storage
