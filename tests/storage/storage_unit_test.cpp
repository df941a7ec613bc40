// Pure functions of storage/: CRC-32, default path, snapshot validation, error texts.
#include "storage/crc32.h"
#include "storage/errors.h"
#include "storage/snapshot.h"
#include "storage/sqlite_archive.h"

#include <gtest/gtest.h>

#include <set>
#include <string_view>

namespace rs4sim::storage {
namespace {

TEST(StorageCrc32, CheckValueOfCrc32IsoHdlc) {
  constexpr std::string_view kCheck = "123456789";
  const auto* p = reinterpret_cast<const std::uint8_t*>(kCheck.data());
  EXPECT_EQ(crc32({p, kCheck.size()}), 0xCBF43926u);
  EXPECT_EQ(crc32({}), 0u);
}

TEST(DefaultArchivePath, FollowsXdgBaseDirectories) {
  EXPECT_EQ(default_archive_path("/data", "/home/u"), "/data/rs4sim/archive.sqlite3");
  EXPECT_EQ(default_archive_path(nullptr, "/home/u"),
            "/home/u/.local/share/rs4sim/archive.sqlite3");
  EXPECT_EQ(default_archive_path("", "/home/u"), "/home/u/.local/share/rs4sim/archive.sqlite3");
  EXPECT_EQ(default_archive_path("relative", "/home/u"),
            "/home/u/.local/share/rs4sim/archive.sqlite3");
  EXPECT_EQ(default_archive_path(nullptr, nullptr), "archive.sqlite3");
}

Snapshot valid_snapshot() {
  Snapshot snap;
  const std::vector<std::uint8_t> blob{'a', 'b', 'c'};
  snap.sets.push_back({1, 0x352441C2u, blob, ""});
  SnapshotStation st;
  st.key = {"b", 4};
  st.versions.push_back({1, 1, {}, VersionSource::kUpload, "", 0, false, "", "", "", {}});
  st.versions.push_back({2, 1, {}, VersionSource::kRestore, "", 1, true, "", "", "", {}});
  st.current_version = 2;
  snap.stations.push_back(st);
  return snap;
}

ArchiveError error_of(const Snapshot& snap) {
  const auto r = validate(snap);
  return r ? ArchiveError{} : r.error().code;
}

TEST(SnapshotValidation, AcceptsASoundSnapshot) { EXPECT_TRUE(validate(valid_snapshot())); }

TEST(SnapshotValidation, RejectsEachKindOfInconsistency) {
  auto s = valid_snapshot();
  s.format_version = 2;
  EXPECT_EQ(error_of(s), ArchiveError::kCorruptImport);
  s = valid_snapshot();
  s.sets[0].crc32 = 0;
  EXPECT_EQ(error_of(s), ArchiveError::kCrcMismatch);
  s = valid_snapshot();
  s.sets.push_back(s.sets[0]);
  EXPECT_EQ(error_of(s), ArchiveError::kCorruptImport);  // set id twice
  s = valid_snapshot();
  s.stations[0].versions[1].number = 1;
  EXPECT_EQ(error_of(s), ArchiveError::kCorruptImport);  // numbers not increasing
  s = valid_snapshot();
  s.stations[0].versions[1].restored_from = 2;
  EXPECT_EQ(error_of(s), ArchiveError::kCorruptImport);  // restores a later version
  s = valid_snapshot();
  s.stations[0].versions[0].source = static_cast<VersionSource>(0);
  EXPECT_EQ(error_of(s), ArchiveError::kCorruptImport);
  s = valid_snapshot();
  s.stations.push_back(s.stations[0]);
  EXPECT_EQ(error_of(s), ArchiveError::kCorruptImport);  // station twice
  s = valid_snapshot();
  s.stations[0].serials.push_back({"", {}, {}});
  EXPECT_EQ(error_of(s), ArchiveError::kCorruptImport);
  s = valid_snapshot();
  s.stations[0].sync_log.push_back({});
  s.stations[0].sync_log[0].direction = static_cast<SyncDirection>(9);
  EXPECT_EQ(error_of(s), ArchiveError::kCorruptImport);
}

TEST(ArchiveErrors, EveryCodeHasItsOwnMessage) {
  std::set<std::string> messages;
  for (int v = 1; v <= static_cast<int>(ArchiveError::kIo); ++v) {
    const auto ec = make_error_code(static_cast<ArchiveError>(v));
    EXPECT_EQ(ec.category().name(), std::string("rs4sim.archive"));
    messages.insert(ec.message());
  }
  EXPECT_EQ(messages.size(), static_cast<std::size_t>(ArchiveError::kIo));
}

}  // namespace
}  // namespace rs4sim::storage
