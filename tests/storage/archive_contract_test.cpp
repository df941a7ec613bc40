// The archive's contract (storage/parameter_archive.h), one suite on every engine: SQLite on a
// real file and PostgreSQL on the real server the ctest fixture started (integration). What
// only one engine has (SQLite's in-memory archive, its parent directory) is tested at the end.
#include "storage/archive_file.h"
#include "storage/sqlite_archive.h"

#include "tests/storage/archive_engines.h"
#include "tests/storage/archive_test_support.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <set>
#include <thread>

namespace rs4sim::storage {
namespace {

using testing::at_ms;
using testing::make_blob;
using testing::request;

const StationKey kStation{"bus1", 4};
const StationKey kOther{"bus1", 5};

class ArchiveContract : public testing::EngineTest {};
using testing::engine_name;

INSTANTIATE_TEST_SUITE_P(Engines, ArchiveContract, ::testing::Values("sqlite", "postgresql"),
                         engine_name);

TEST_P(ArchiveContract, StoreMakesANewCurrentVersion) {
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

TEST_P(ArchiveContract, VersionNumbersArePerStation) {
  archive_->store(request(kStation, make_blob(1))).value();
  archive_->store(request(kStation, make_blob(2))).value();
  const auto other = archive_->store(request(kOther, make_blob(3))).value();
  EXPECT_EQ(other.number, 1u);
}

TEST_P(ArchiveContract, SameBytesShareOneSet) {
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

TEST_P(ArchiveContract, HistoryAndGet) {
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

TEST_P(ArchiveContract, RestoreIsANewCurrentVersionPendingDownload) {
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

TEST_P(ArchiveContract, ANewStoreSupersedesAPendingRestore) {
  const auto v1 = archive_->store(request(kStation, make_blob(1))).value();
  const auto r = archive_->restore(v1.id, at_ms(2), "").value();
  archive_->store(request(kStation, make_blob(3))).value();
  EXPECT_FALSE(archive_->get(r.id).value().version.pending_download);
}

TEST_P(ArchiveContract, StationsWithSerialNumbersSeen) {
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

TEST_P(ArchiveContract, SyncLogKeepsTheNewestEntriesOldestFirst) {
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

TEST_P(ArchiveContract, IntegrityCheckPassesAndFindsABadBlob) {
  archive_->store(request(kStation, make_blob(1))).value();
  EXPECT_TRUE(archive_->check_integrity().value().ok());
  engine_->damage_blobs();  // behind the archive's back
  const auto report = archive_->check_integrity().value();
  // PostgreSQL also keeps each blob's SHA-256 (its deduplication key) and finds that broken.
  ASSERT_GE(report.problems.size(), 2u);
  EXPECT_EQ(report.problems[0], "parameter set 1: CRC-32 does not match its blob");
  EXPECT_EQ(report.problems[1], "parameter set 1: size does not match its blob");
}

TEST_P(ArchiveContract, ReopenKeepsEverything) {
  const auto v = archive_->store(request(kStation, make_blob(1))).value();
  archive_.reset();
  auto again = engine_->open();
  EXPECT_EQ(again->current(kStation).value().version, v);
}

TEST_P(ArchiveContract, TimesKeepTheirMillisecondAndTextItsBytes) {
  const auto blob = make_blob(1);
  auto r = request({"Linie 3 / Halle Süd", 126}, blob, 1'796'025'600'123);
  r.note = "Überprüfung nach Gerätetausch; O'Brien said \"ok\"";
  r.serial_number = "0815-ÄÖÜ";
  const auto v = archive_->store(r).value();
  EXPECT_EQ(v.at, at_ms(1'796'025'600'123));
  archive_->log_sync({r.station, at_ms(-1500), "before the epoch", SyncDirection::kVerify,
                      SyncOutcome::kAborted, 0xFFFFFFFFu, 0x80000000u, 1,
                      std::chrono::milliseconds{86'400'000}})
      .value();
  archive_.reset();
  archive_ = engine_->open();
  const auto again = archive_->current(r.station).value();
  EXPECT_EQ(again.version, v);
  EXPECT_EQ(again.version.note, r.note);
  EXPECT_EQ(again.version.serial_number, r.serial_number);
  const auto log = archive_->sync_log(r.station, 1).value();
  ASSERT_EQ(log.size(), 1u);
  EXPECT_EQ(log[0].at, at_ms(-1500));
  EXPECT_EQ(log[0].error_number_fb, 0xFFFFFFFFu);
  EXPECT_EQ(log[0].error_code_sfc, 0x80000000u);
  EXPECT_EQ(log[0].duration, std::chrono::milliseconds{86'400'000});
}

// Several writers (each its own connection, as several masters) on one station at once: every
// version is numbered exactly once, 1..N without a gap, none is lost, and a set they all store
// is kept once.
TEST_P(ArchiveContract, ConcurrentWritersNumberEveryVersionOnceAndLoseNone) {
  constexpr int kWriters = 4;
  constexpr int kStores = 15;
  const auto shared = make_blob(7);
  std::vector<std::thread> writers;
  std::vector<std::vector<VersionInfo>> stored(kWriters);
  std::vector<std::string> errors(kWriters);
  for (int w = 0; w < kWriters; ++w) {
    writers.emplace_back([&, w] {
      auto archive = engine_->open();
      for (int i = 0; i < kStores; ++i) {
        const auto blob =
            i % 5 == 0 ? shared : make_blob(static_cast<std::uint64_t>(1000 * (w + 1) + i));
        auto result = archive->store(request(kStation, blob, 1'700'000'000'000 + i));
        if (!result) {
          errors[static_cast<std::size_t>(w)] = result.error().message;
          return;
        }
        stored[static_cast<std::size_t>(w)].push_back(result.value());
      }
    });
  }
  for (auto& t : writers) t.join();
  for (const auto& e : errors) ASSERT_EQ(e, "");
  const auto history = archive_->history(kStation).value();
  ASSERT_EQ(history.size(), static_cast<std::size_t>(kWriters * kStores));
  std::set<VersionId> ids;
  for (std::size_t i = 0; i < history.size(); ++i) {
    EXPECT_EQ(history[i].number, i + 1);
    ids.insert(history[i].id);
  }
  EXPECT_EQ(ids.size(), history.size());
  for (const auto& mine : stored) {
    for (const auto& v : mine) EXPECT_EQ(history[v.number - 1], v);
  }
  EXPECT_EQ(archive_->current(kStation).value().version, history.back());
  // 3 stores of each writer are the shared set: one row for all of them.
  const auto snap = archive_->export_snapshot(at_ms(0)).value();
  EXPECT_EQ(snap.sets.size(), static_cast<std::size_t>(kWriters * (kStores - 3) + 1));
  EXPECT_TRUE(archive_->check_integrity().value().ok());
}

// Who stored a version, from where, and the station's site and line (docs/storage.md "What
// maintenance records"): recorded as given, an empty site or line keeps the stored one.
TEST_P(ArchiveContract, EveryVersionRecordsWhoAndWhereAndTheStationItsSite) {
  const auto blob1 = make_blob(1);
  const auto blob2 = make_blob(2);
  auto r = request(kStation, blob1, 1000);
  r.user = "jdoe";
  r.host = "ws-maint-03";
  r.site = "Hamburg";
  r.line = "Press line 2";
  r.note = "commissioning";
  const auto v1 = archive_->store(r).value();
  EXPECT_EQ(v1.user, "jdoe");
  EXPECT_EQ(v1.host, "ws-maint-03");
  EXPECT_EQ(v1.note, "commissioning");

  auto later = request(kStation, blob2, 2000);  // no site, no line, no user given
  const auto v2 = archive_->store(later).value();
  EXPECT_EQ(v2.user, "");
  const auto list = archive_->stations().value();
  ASSERT_EQ(list.size(), 1u);
  EXPECT_EQ(list[0].site, "Hamburg");
  EXPECT_EQ(list[0].line, "Press line 2");

  const auto back = archive_->restore(v1.id, at_ms(3000), "undo", Author{"asmith", "ws-07"}).value();
  EXPECT_EQ(back.user, "asmith");
  EXPECT_EQ(back.host, "ws-07");
  EXPECT_EQ(archive_->history(kStation).value().back(), back);
  EXPECT_EQ(archive_->get(v1.id).value().version, v1);
}

// The option to store nothing when the set is the current one: the current version comes back
// unchanged; a set that is stored but not current is a new version.
TEST_P(ArchiveContract, SkipIdenticalStoresNoVersionForTheCurrentSet) {
  const auto a = make_blob(1);
  const auto v1 = archive_->store(request(kStation, a, 1000)).value();
  auto again = request(kStation, a, 2000);
  again.skip_identical = true;
  again.serial_number = "SN-2";
  EXPECT_EQ(archive_->store(again).value(), v1);
  EXPECT_EQ(archive_->history(kStation).value().size(), 1u);
  const auto serials = archive_->stations().value().at(0).serials;  // still seen
  ASSERT_EQ(serials.size(), 2u);
  EXPECT_EQ(serials[1].serial_number, "SN-2");

  const auto blob_b = make_blob(2);
  auto b = request(kStation, blob_b, 3000);
  b.skip_identical = true;
  EXPECT_EQ(archive_->store(b).value().number, 2u);
  again.at = at_ms(4000);
  const auto v3 = archive_->store(again).value();  // `a` is stored, but no longer current
  EXPECT_EQ(v3.number, 3u);
  EXPECT_EQ(v3.set_id, v1.set_id);
  // The same bytes current at another station do not count.
  auto other = request(kOther, a, 5000);
  other.skip_identical = true;
  EXPECT_EQ(archive_->store(other).value().number, 1u);
}

TEST_P(ArchiveContract, ANoteReplacesTheCommentAndNothingElse) {
  const auto v1 = archive_->store(request(kStation, make_blob(1), 1000)).value();
  const auto noted = archive_->annotate(v1.id, "replaced after the crash on 2 Dec").value();
  auto expected = v1;
  expected.note = "replaced after the crash on 2 Dec";
  EXPECT_EQ(noted, expected);
  EXPECT_EQ(archive_->current(kStation).value().version, expected);
  EXPECT_EQ(archive_->annotate(v1.id, "").value().note, "");
}

// The change feed's reads: every version above an id, ascending, at most `limit`.
TEST_P(ArchiveContract, VersionsAfterAnIdAreTheChangeFeed) {
  const auto a = archive_->store(request(kStation, make_blob(1), 1000)).value();
  const auto b = archive_->store(request(kOther, make_blob(2), 2000)).value();
  const auto c = archive_->restore(a.id, at_ms(3000), "r").value();
  EXPECT_EQ(archive_->versions_after(0, 100).value(), (std::vector<VersionInfo>{a, b, c}));
  EXPECT_EQ(archive_->versions_after(a.id, 1).value(), (std::vector<VersionInfo>{b}));
  EXPECT_TRUE(archive_->versions_after(c.id, 100).value().empty());
}

// Either engine's export imports into the other unchanged (what `archive copy` builds on).
TEST_P(ArchiveContract, AnExportOfOneEngineImportsIntoTheOther) {
  const auto blob1 = make_blob(1);
  auto first = request(kStation, blob1, 1000);
  first.user = "jdoe";
  first.host = "ws-1";
  first.site = "Hamburg";
  first.line = "L2";
  const auto v1 = archive_->store(first).value();
  archive_->store(request(kOther, make_blob(1), 2000)).value();
  archive_->restore(v1.id, at_ms(3000), "restore", Author{"asmith", "ws-2"}).value();
  archive_
      ->log_sync({kStation, at_ms(4000), "PC adapter removed", SyncDirection::kDownload,
                  SyncOutcome::kSucceeded, 0, 0, 0, std::chrono::milliseconds{42}})
      .value();
  const auto expected = archive_->export_snapshot(at_ms(9000)).value();
  const auto other = testing::make_engine(GetParam() == "sqlite" ? "postgresql" : "sqlite");
  if (!other) GTEST_SKIP() << "no PostgreSQL server (tests/storage/postgres_server.sh)";
  auto target = other->open();
  import_binary(*target, export_binary(*archive_, at_ms(9000)).value()).value();
  EXPECT_EQ(target->export_snapshot(at_ms(9000)).value(), expected);
  EXPECT_TRUE(target->check_integrity().value().ok());
}

// Every refused call: the specific code, a message naming the object, and the stored rows
// unchanged (read by the engine's own client library before and after).
class ArchiveContractErrors : public ArchiveContract {
 protected:
  void SetUp() override {
    ArchiveContract::SetUp();
    if (IsSkipped()) return;
    first_ = archive_->store(request(kStation, make_blob(1))).value();
    archive_
        ->log_sync({kStation, at_ms(1), "r", SyncDirection::kVerify, SyncOutcome::kSucceeded, 0, 0,
                    0, std::chrono::milliseconds{1}})
        .value();
    before_ = engine_->digest();
  }
  template <class T>
  void expect_error(const Result<T>& r, ArchiveError code, const std::string& text) {
    ASSERT_TRUE(r.has_error());
    EXPECT_EQ(r.error().code, code) << r.error().message;
    EXPECT_THAT(r.error().message, ::testing::HasSubstr(text));
    EXPECT_EQ(engine_->digest(), before_);
  }
  VersionInfo first_;
  std::string before_;
};

INSTANTIATE_TEST_SUITE_P(Engines, ArchiveContractErrors,
                         ::testing::Values("sqlite", "postgresql"), engine_name);

TEST_P(ArchiveContractErrors, UnknownStation) {
  const StationKey nobody{"bus9", 9};
  expect_error(archive_->current(nobody), ArchiveError::kUnknownStation,
               "current: station bus9/9: unknown station");
  expect_error(archive_->history(nobody), ArchiveError::kUnknownStation, "station bus9/9");
  expect_error(archive_->sync_log(nobody, 10), ArchiveError::kUnknownStation, "bus9/9");
  // The error names the stations the archive has, so that a wrong --bus shows at once.
  expect_error(archive_->current(nobody), ArchiveError::kUnknownStation,
               "unknown station (the archive has bus bus1: 4)");
  archive_->store(request({"bus1", 12}, make_blob(2))).value();
  archive_->store(request({"line2", 7}, make_blob(3))).value();
  before_ = engine_->digest();
  expect_error(archive_->history(nobody), ArchiveError::kUnknownStation,
               "(the archive has bus bus1: 4, 12; bus line2: 7)");
}

TEST_P(ArchiveContractErrors, StationWithoutCurrentSet) {
  archive_
      ->log_sync({{"bus2", 7}, at_ms(1), "r", SyncDirection::kNone, SyncOutcome::kFailed, 1, 2, 3,
                  std::chrono::milliseconds{0}})
      .value();
  before_ = engine_->digest();
  expect_error(archive_->current({"bus2", 7}), ArchiveError::kNotFound,
               "station bus2/7 has no current set");
}

TEST_P(ArchiveContractErrors, UnknownVersion) {
  expect_error(archive_->get(999), ArchiveError::kUnknownVersion, "get: version 999");
  expect_error(archive_->restore(999, at_ms(1), ""), ArchiveError::kUnknownVersion,
               "restore: version 999: unknown version");
  expect_error(archive_->mark_downloaded(999), ArchiveError::kUnknownVersion, "version 999");
}

TEST_P(ArchiveContractErrors, CrcClaimMismatch) {
  const auto blob = make_blob(2);
  auto r = request(kStation, blob);
  r.crc32 ^= 1;
  expect_error(archive_->store(r), ArchiveError::kCrcMismatch, "store station bus1/4: claimed 0x");
}

TEST_P(ArchiveContractErrors, InvalidRequests) {
  const std::vector<std::uint8_t> empty;
  expect_error(archive_->store(request(kStation, empty)), ArchiveError::kInvalidArgument,
               "empty blob");
  expect_error(archive_->store(request({"bus1", 127}, make_blob(2))), ArchiveError::kInvalidArgument,
               "address 127 above 126");
  expect_error(archive_->log_sync({{"bus1", 200}, at_ms(1), "r", SyncDirection::kNone,
                                   SyncOutcome::kFailed, 0, 0, 0, std::chrono::milliseconds{0}}),
               ArchiveError::kInvalidArgument, "address 200 above 126");
}

TEST_P(ArchiveContractErrors, TextsThatAreNotUtf8OrTooLongAreRefused) {
  const auto blob = make_blob(2);
  auto r = request(kStation, blob);
  r.note = "bad \xFF byte";
  expect_error(archive_->store(r), ArchiveError::kInvalidArgument, "note: byte 4 is not UTF-8");
  r.note = "";
  r.user = std::string("a\0b", 3);
  expect_error(archive_->store(r), ArchiveError::kInvalidArgument, "user: byte 1 is NUL");
  r.user = "";
  r.site = std::string(257, 's');
  expect_error(archive_->store(r), ArchiveError::kInvalidArgument,
               "site of 257 bytes (at most 256)");
  r.site = "Zürich";  // UTF-8 is fine
  r.host = "\xC3\x28";  // a lead byte without its continuation
  expect_error(archive_->store(r), ArchiveError::kInvalidArgument, "host: byte 0 is not UTF-8");
  expect_error(archive_->annotate(first_.id, std::string(4097, 'n')),
               ArchiveError::kInvalidArgument, "note of 4097 bytes (at most 4096)");
  expect_error(archive_->annotate(999, "x"), ArchiveError::kUnknownVersion, "version 999");
  expect_error(archive_->restore(first_.id, at_ms(5), "\xED\xA0\x80"),  // a UTF-16 surrogate
               ArchiveError::kInvalidArgument, "note: byte 0 is not UTF-8");
}

TEST_P(ArchiveContractErrors, ImportWithACrcMismatchOrBadReferenceWritesNothing) {
  auto snap = archive_->export_snapshot(at_ms(0)).value();
  snap.stations[0].key.bus = "bus2";  // would be a new station
  auto bad_crc = snap;
  bad_crc.sets[0].crc32 ^= 0x80000000u;
  expect_error(import_binary(*archive_, encode_binary(bad_crc)), ArchiveError::kCrcMismatch,
               "parameter set 1: CRC-32 does not match its blob");
  auto bad_ref = snap;
  bad_ref.stations[0].versions[0].set_id = 77;
  expect_error(import_json(*archive_, encode_json(bad_ref)), ArchiveError::kCorruptImport,
               "station bus2/4 version 1: unknown parameter set");
  auto bad_current = snap;
  bad_current.stations[0].current_version = 5;
  expect_error(archive_->import_snapshot(bad_current), ArchiveError::kCorruptImport,
               "current version 5 not in its versions");
}

TEST_P(ArchiveContractErrors, EveryTextAWriteTakesIsCheckedByTheWriters) {
  const auto blob = make_blob(2);
  auto r = request(StationKey{std::string("bus\0x", 5), 4}, blob);
  expect_error(archive_->store(r), ArchiveError::kInvalidArgument, "bus: byte 3 is NUL");
  r = request(kStation, blob);
  r.device_type = std::string("RS4\0", 4);
  expect_error(archive_->store(r), ArchiveError::kInvalidArgument, "device type: byte 3 is NUL");
  r.device_type = "";
  r.serial_number = "\xFF";
  expect_error(archive_->store(r), ArchiveError::kInvalidArgument,
               "serial number: byte 0 is not UTF-8");
  r.serial_number = "";
  r.summary = std::string("a\0", 2);
  expect_error(archive_->store(r), ArchiveError::kInvalidArgument, "summary: byte 1 is NUL");
  expect_error(archive_->log_sync({kStation, at_ms(2), std::string("re\0", 3),
                                   SyncDirection::kVerify, SyncOutcome::kSucceeded, 0, 0, 0,
                                   std::chrono::milliseconds{1}}),
               ArchiveError::kInvalidArgument, "reason: byte 2 is NUL");
}

// An export whose station's bus is "a\u0000b": refused on both engines, nothing written
// (PostgreSQL cut such a name to "a" and appended its versions to station a/4).
TEST_P(ArchiveContractErrors, ImportOfANameWithANulIsRefused) {
  archive_->store(request(StationKey{"a", 4}, make_blob(3))).value();
  before_ = engine_->digest();
  auto snap = archive_->export_snapshot(at_ms(0)).value();
  for (auto& st : snap.stations) {
    if (st.key.bus == "a") st.key.bus = std::string("a\0b", 3);
  }
  const auto json = encode_json(snap);
  ASSERT_NE(json.find("a\\u0000b"), std::string::npos);  // as JSON writes it
  expect_error(import_json(*archive_, json), ArchiveError::kCorruptImport,
               "station \"a\\u0000b\"/4: bus: byte 1 is NUL");
  expect_error(import_binary(*archive_, encode_binary(snap)), ArchiveError::kCorruptImport,
               "bus: byte 1 is NUL");
  auto serial = archive_->export_snapshot(at_ms(0)).value();
  serial.stations[0].versions.at(0).serial_number = std::string("08\0", 3);
  expect_error(archive_->import_snapshot(serial), ArchiveError::kCorruptImport,
               "version 1: serial number: byte 2 is NUL");
  auto reason = archive_->export_snapshot(at_ms(0)).value();
  reason.stations[1].sync_log.at(0).reason = "\xC0";  // bus1/4's (a/4 comes first)
  expect_error(archive_->import_snapshot(reason), ArchiveError::kCorruptImport,
               "sync log entry: reason: byte 0 is not UTF-8");
}

TEST_P(ArchiveContractErrors, ImportOfAStationWithoutVersionsOrSyncLogIsRefused) {
  auto snap = archive_->export_snapshot(at_ms(0)).value();
  snap.stations.push_back(snap.stations[0]);
  snap.stations.back().key = StationKey{"empty", 9};
  snap.stations.back().versions.clear();
  snap.stations.back().current_version = 0;
  auto only_log = snap;  // a station only a sync log made (log_sync does): kept
  snap.stations.back().sync_log.clear();
  expect_error(import_json(*archive_, encode_json(snap)), ArchiveError::kCorruptImport,
               "station empty/9: no versions and no sync log");
  EXPECT_TRUE(import_json(*archive_, encode_json(only_log)).has_value());
}

TEST(SqliteArchiveOnly, InMemoryArchive) {
  auto mem = SqliteArchive::open(":memory:").value();
  mem->store(request(kStation, make_blob(1))).value();
  EXPECT_EQ(mem->history(kStation).value().size(), 1u);
}

TEST(SqliteArchiveOnly, CreatesTheParentDirectory) {
  testing::TempDir dir;
  const auto deep = dir.file("a/b/archive.sqlite3");
  auto a = SqliteArchive::open(deep).value();
  EXPECT_TRUE(std::filesystem::exists(deep));
}

TEST_P(ArchiveContract, SavedProxyStateSurvivesReopenAndIsReplaced) {
  const StationKey station{"bus1", 4};
  EXPECT_EQ(archive_->load_proxy_state(station).error().code, ArchiveError::kNotFound);
  const std::vector<std::uint8_t> first{0x01, 0x02, 0x03};
  archive_->save_proxy_state(station, first, testing::at_ms(1000)).value();
  const std::vector<std::uint8_t> second(34, 0xA5);  // the FB's 34 retentive bytes
  archive_->save_proxy_state(station, second, testing::at_ms(2000)).value();
  archive_.reset();
  archive_ = engine_->open();
  EXPECT_EQ(archive_->load_proxy_state(station).value(), second);
  // Per address and bus; no station row is needed, none is created.
  EXPECT_EQ(archive_->load_proxy_state({"bus1", 5}).error().code, ArchiveError::kNotFound);
  EXPECT_EQ(archive_->load_proxy_state({"bus2", 4}).error().code, ArchiveError::kNotFound);
  EXPECT_TRUE(archive_->stations().value().empty());
  EXPECT_TRUE(archive_->check_integrity().value().ok());
}

TEST_P(ArchiveContract, BadProxyStateIsRefusedAndNothingChanges) {
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
