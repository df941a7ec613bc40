// Export/import file: round trips through binary and JSON, a hand-written JSON file and a
// hand-annotated binary message as known answers (integration: real SQLite files).
#include "storage/archive_file.h"

#include "storage/sqlite_archive.h"
#include "tests/storage/archive_test_support.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace rs4sim::storage {
namespace {

using testing::at_ms;
using testing::make_blob;
using testing::request;

// ArchiveExport written out by hand, one field per line: (field number << 3) | wire type.
const std::vector<std::uint8_t> kAnnotatedBinary = {
    0x08, 0x01,                    // 1 format_version, varint: 1
    0x12, 0x02,                    // 2 exported_at, length 2 (google.protobuf.Timestamp)
    0x08, 0x01,                    //   1 seconds, varint: 1 (1970-01-01T00:00:01Z)
    0x1A, 0x13,                    // 3 stations[0], length 19
    0x0A, 0x01, 'b',               //   1 bus, length 1: "b"
    0x10, 0x04,                    //   2 address, varint: 4
    0x2A, 0x0A,                    //   5 versions[0], length 10
    0x08, 0x01,                    //     1 number: 1
    0x10, 0x01,                    //     2 parameter_set_id: 1
    0x1A, 0x02, 0x08, 0x02,        //     3 stored_at, length 2: seconds 2
    0x20, 0x01,                    //     4 source: 1 = VERSION_SOURCE_UPLOAD
    0x30, 0x01,                    //   6 current_version: 1
    0x22, 0x0C,                    // 4 parameter_sets[0], length 12
    0x08, 0x01,                    //   1 id: 1
    0x15, 0xC2, 0x41, 0x24, 0x35,  //   2 crc32, fixed32 little-endian: 0x352441C2
    0x1A, 0x03, 'a',  'b',  'c',   //   3 blob, length 3: "abc"
};

TEST(ArchiveFile, AnnotatedBinaryDecodesToTheExpectedValues) {
  const auto snap = decode_binary(kAnnotatedBinary).value();
  EXPECT_EQ(snap.format_version, 1u);
  EXPECT_EQ(snap.exported_at, at_ms(1000));
  ASSERT_EQ(snap.sets.size(), 1u);
  EXPECT_EQ(snap.sets[0].id, 1);
  EXPECT_EQ(snap.sets[0].crc32, 0x352441C2u);
  EXPECT_EQ(snap.sets[0].blob, (std::vector<std::uint8_t>{'a', 'b', 'c'}));
  ASSERT_EQ(snap.stations.size(), 1u);
  const auto& st = snap.stations[0];
  EXPECT_EQ(st.key, (StationKey{"b", 4}));
  EXPECT_EQ(st.current_version, 1u);
  ASSERT_EQ(st.versions.size(), 1u);
  EXPECT_EQ(st.versions[0],
            (SnapshotVersion{1, 1, at_ms(2000), VersionSource::kUpload, "", 0, false, "", "", "", {}}));
  // And our encoder writes exactly these bytes for it.
  EXPECT_EQ(encode_binary(snap), kAnnotatedBinary);
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ArchiveFile, HandWrittenJsonImportsToTheExpectedRows) {
  auto archive = SqliteArchive::open(":memory:").value();
  const auto summary =
      import_json(*archive, read_text(RS4SIM_STORAGE_DATA + "/archive_v1.json")).value();
  EXPECT_EQ(summary.stations, 1u);
  EXPECT_EQ(summary.versions, 3u);
  EXPECT_EQ(summary.new_sets, 2u);
  EXPECT_EQ(summary.sync_log_entries, 1u);

  const StationKey station{"line1", 5};
  const auto history = archive->history(station).value();
  ASSERT_EQ(history.size(), 3u);
  EXPECT_EQ(history[0].note, "commissioning");
  EXPECT_EQ(history[0].at, at_ms(1796025600000));
  EXPECT_EQ(history[0].crc32, 0x352441C2u);
  EXPECT_EQ(history[1].at, at_ms(1796027400250));
  EXPECT_EQ(history[1].crc32, 0xEB8EBA67u);
  EXPECT_EQ(history[2].source, VersionSource::kRestore);
  EXPECT_EQ(history[2].restored_from, history[0].id);
  EXPECT_EQ(history[2].set_id, history[0].set_id);
  EXPECT_TRUE(history[2].pending_download);

  const auto cur = archive->current(station).value();
  EXPECT_EQ(cur.version.id, history[2].id);
  EXPECT_EQ(cur.set.summary, "set abc");
  const auto list = archive->stations().value();
  ASSERT_EQ(list.size(), 1u);
  EXPECT_EQ(list[0].device_type, "RS4/PROFIsafe");
  EXPECT_EQ(list[0].serials,
            (std::vector<SerialSeen>{{"0815", at_ms(1796025600000), at_ms(1796029200000)}}));
  const auto log = archive->sync_log(station, 10).value();
  ASSERT_EQ(log.size(), 1u);
  EXPECT_EQ(log[0],
            (SyncLogEntry{station, at_ms(1796029205000), "power-up check", SyncDirection::kDownload,
                          SyncOutcome::kFailed, 0x2B09, 0, 0, std::chrono::milliseconds{1500}}));
}

class ArchiveRoundTrip : public ::testing::Test {
 protected:
  void SetUp() override {
    source_ = SqliteArchive::open(dir_.file("a.sqlite3")).value();
    const StationKey s1{"bus1", 4};
    const StationKey s2{"bus2", 126};
    const auto v1 = source_->store(request(s1, make_blob(1), 1000)).value();
    source_->store(request(s1, make_blob(2), 2000)).value();
    source_->store(request(s2, make_blob(1), 3000)).value();  // shares a set
    source_->restore(v1.id, at_ms(4000), "restore").value();
    source_
        ->log_sync({s1, at_ms(5000), "PC adapter removed", SyncDirection::kDownload,
                    SyncOutcome::kSucceeded, 0, 0, 0, std::chrono::milliseconds{42}})
        .value();
    expected_ = source_->export_snapshot(at_ms(9000)).value();
  }
  testing::TempDir dir_;
  std::unique_ptr<SqliteArchive> source_;
  Snapshot expected_;
};

TEST_F(ArchiveRoundTrip, Binary) {
  auto target = SqliteArchive::open(dir_.file("b.sqlite3")).value();
  import_binary(*target, export_binary(*source_, at_ms(9000)).value()).value();
  EXPECT_EQ(target->export_snapshot(at_ms(9000)).value(), expected_);
  EXPECT_TRUE(target->check_integrity().value().ok());
}

TEST_F(ArchiveRoundTrip, Json) {
  auto target = SqliteArchive::open(dir_.file("b.sqlite3")).value();
  import_json(*target, export_json(*source_, at_ms(9000)).value()).value();
  EXPECT_EQ(target->export_snapshot(at_ms(9000)).value(), expected_);
}

// The file's own versions are recognised (archive_import_test.cpp); another archive's are
// appended, renumbered, with their restore references and sets shared.
TEST_F(ArchiveRoundTrip, ImportIntoANonEmptyArchiveAppendsAndDeduplicates) {
  auto target = SqliteArchive::open(dir_.file("b.sqlite3")).value();
  const auto own = target->store(request({"bus1", 4}, make_blob(2), 500)).value();
  const auto summary = target->import_snapshot(expected_).value();
  EXPECT_EQ(summary.new_sets, 1u);  // blob 2 is already there
  const auto history = target->history({"bus1", 4}).value();
  ASSERT_EQ(history.size(), 4u);
  EXPECT_EQ(history[1].number, 2u);  // the file's version 1, renumbered
  EXPECT_EQ(history[2].set_id, own.set_id);
  EXPECT_EQ(history[3].restored_from, history[1].id);
  EXPECT_EQ(target->current({"bus1", 4}).value().version.id, own.id);
  EXPECT_EQ(target->sync_log({"bus1", 4}, 10).value().size(), 1u);
}

TEST(ArchiveFile, TimestampsBeforeTheEpochSurvive) {
  Snapshot snap;
  snap.exported_at = at_ms(-1500);
  EXPECT_EQ(decode_binary(encode_binary(snap)).value().exported_at, at_ms(-1500));
  EXPECT_EQ(decode_json(encode_json(snap)).value().exported_at, at_ms(-1500));
}

// The refusal of a JSON file: its message, or "decoded".
std::string refusal(std::string_view text) {
  const auto r = decode_json(text);
  return r ? "decoded" : r.error().message;
}

TEST(ArchiveFile, ArraysInArraysAreRefusedNotFlattened) {
  // { 0, "formatVersion" 1-15, : 16, 1 17, , 18, "stations" 19-28, : 29, [ 30, [ 31
  EXPECT_EQ(refusal(R"({"formatVersion":1,"stations":[[]]})"),
            "not a JSON rs4sim.v1.ArchiveExport: 1:32: an array directly inside an array "
            "(this format has none): corrupt import file");
  EXPECT_EQ(refusal(R"({"formatVersion":1,"stations":[[{"bus":"a"}]]})").substr(0, 41),
            "not a JSON rs4sim.v1.ArchiveExport: 1:32:");
  // 50,000 objects in each other, refused by the structure scan at the bracket that opens
  // depth 101: {"formatVersion": is offsets 0-16, then {"a": (5 bytes) at 17 + 5k opens depth
  // k + 1; k = 100 at offset 517: line 1, column 518.
  std::string deep = R"({"formatVersion":)";
  for (int k = 0; k < 50'000; ++k) deep += R"({"a":)";
  deep += "1" + std::string(50'001, '}');
  EXPECT_EQ(refusal(deep),
            "not a JSON rs4sim.v1.ArchiveExport: 1:518: nested deeper than 100: corrupt import "
            "file");
}

TEST(ArchiveFile, JsonRefusalsNameLineAndColumn) {
  // Line 3: two spaces, "stations" at 3-12, : 13, space 14, [ 15, } 16
  EXPECT_EQ(refusal("{\n  \"formatVersion\": 1,\n  \"stations\": [}\n"),
            "not a JSON rs4sim.v1.ArchiveExport: 3:16: expected a value: corrupt import file");
  // Line 4: five spaces, "source" at 6-13, : 14, space 15, "NOPE" from 16 (protobuf names
  // the member, the line and column are found in the text).
  const std::string bad_enum = "{\"formatVersion\": 1,\n \"stations\": [{\"bus\": \"a\",\n"
                               "   \"versions\": [{\"number\": 1,\n     \"source\": \"NOPE\"}]}]}";
  EXPECT_EQ(refusal(bad_enum).rfind("not a JSON rs4sim.v1.ArchiveExport: 4:16: "
                                    "(stations[0].versions[0].source): invalid value \"NOPE\"",
                                    0),
            0u)
      << refusal(bad_enum);
  // Line 2: space, "stations" 2-11, : 12, space 13, [ 14, { 15, "bus" 16-20, : 21, space 22,
  // "a" 23-25, , 26, space 27, "colour" 28-35, : 36, space 37, 1 at 38
  EXPECT_EQ(refusal("{\"formatVersion\": 1,\n \"stations\": [{\"bus\": \"a\", \"colour\": 1}]}"),
            "not a JSON rs4sim.v1.ArchiveExport: 2:38: (stations[0]) colour: Cannot find "
            "field.: corrupt import file");
}

TEST(ArchiveFile, ALongValueIsNotRepeatedInFull) {
  const std::string huge = "{\"formatVersion\": 1, \"stations\": [{\"versions\": [{\"source\": \"" +
                           std::string(10'000'000, 'x') + "\"}]}]}";
  const auto message = refusal(huge);
  EXPECT_LT(message.size(), 400u) << message.size();
  EXPECT_NE(message.find("(10000"), std::string::npos) << message;  // "… (N bytes)"
}

}  // namespace
}  // namespace rs4sim::storage
