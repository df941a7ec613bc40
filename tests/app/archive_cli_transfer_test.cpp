// `rs4sim archive export|import|restore|verify` and every refusal: a specific message on
// stderr, exit 2 for usage errors and 1 for the others, and the archive unchanged.
#include "archive_cli_fixture.h"

#include <sqlite3.h>

namespace rs4sim::app::testing {
namespace {

void sql(const std::filesystem::path& file, const std::string& statement) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(file.c_str(), &db), SQLITE_OK);
  EXPECT_EQ(sqlite3_exec(db, statement.c_str(), nullptr, nullptr, nullptr), SQLITE_OK)
      << sqlite3_errmsg(db);
  sqlite3_close(db);
}

TEST_F(ArchiveCli, ExportImportRoundTripsBothFormats) {
  for (const std::string name : {"export.json", "export.pb"}) {
    const auto file = dir_ / name;
    const auto copy = dir_ / ("copy-" + name + ".sqlite3");
    auto r = run("export '" + file.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("exported 2 stations, 3 versions, 3 sets to"), std::string::npos) << r.out;
    r = run("import '" + file.string() + "' --json", copy.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const ptree doc = parse_json(r.out);
    EXPECT_EQ(doc.get<int>("stations"), 2);
    EXPECT_EQ(doc.get<int>("versions"), 3);
    EXPECT_EQ(doc.get<int>("new_sets"), 3);
    EXPECT_EQ(doc.get<int>("sync_log_entries"), 1);
    const auto diff = run("diff 1 2", copy.string());
    EXPECT_NE(diff.out.find("pair 2 protective: segments 100-140 changed, max +350 mm"),
              std::string::npos);
  }
  EXPECT_EQ(read_text(dir_ / "export.json").front(), '{');
  // --format wins over the extension.
  const auto r = run("export '" + (dir_ / "x.bin").string() + "' --format json --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(parse_json(r.out).get<std::string>("format"), "json");
  EXPECT_EQ(read_text(dir_ / "x.bin").front(), '{');
}

TEST_F(ArchiveCli, RestoreMakesAPendingVersion) {
  auto r = run("restore 1 --note 'back to commissioning' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const ptree doc = parse_json(r.out);
  EXPECT_EQ(doc.get<int>("version.id"), 4);
  EXPECT_EQ(doc.get<int>("version.number"), 3);
  EXPECT_EQ(doc.get<int>("version.restored_from"), 1);
  EXPECT_TRUE(doc.get<bool>("version.pending_download"));
  EXPECT_EQ(doc.get<std::string>("version.source"), "restore");
  r = run("history --address 4");
  EXPECT_NE(r.out.find("current, pending download, restores 1  back to commissioning"),
            std::string::npos)
      << r.out;
  EXPECT_NE(run("diff 2 4").out.find("max -350 mm"), std::string::npos);
}

TEST_F(ArchiveCli, VerifyPassesAndFindsABadBlob) {
  auto r = run("verify");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find(": ok (2 stations)"), std::string::npos) << r.out;
  sql(archive_, "UPDATE parameter_sets SET blob = zeroblob(8507) WHERE id = 1");
  expect_refusal("verify", 1, "problem");
  r = run("verify --json");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_FALSE(parse_json(r.out).get<bool>("ok"));
}

TEST_F(ArchiveCli, UsageErrorsExitTwo) {
  const std::string before = contents();
  for (const std::string args :
       {"history", "history --address 127", "show", "show 1 2", "show 1 --address 4", "diff",
        "diff 1 2 3", "restore", "restore 1 2", "export", "import", "export x.json --format xml"}) {
    const auto r = run(args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find("rs4sim: archive "), std::string::npos) << args << ": " << r.err;
  }
  EXPECT_EQ(contents(), before);
}

TEST_F(ArchiveCli, UnknownStationAndVersion) {
  const std::string before = contents();
  expect_refusal("show 99", 1, "unknown version");
  expect_refusal("restore 99", 1, "unknown version");
  const auto r = expect_refusal("history --bus nowhere --address 4", 1, "unknown station");
  // … and names what the archive has (the fixture's default/4 and line2/5).
  EXPECT_NE(r.err.find("(the archive has bus default: 4; bus line2: 5)"), std::string::npos)
      << r.err;
  expect_refusal("diff --bus line2 --address 5", 1, "has no version before");
  EXPECT_EQ(contents(), before);
}

TEST_F(ArchiveCli, BadImportFilesChangeNothing) {
  const std::string before = contents();
  ASSERT_EQ(run("export '" + (dir_ / "good.json").string() + "'").exit_code, 0);
  const std::string good = read_text(dir_ / "good.json");
  // A CRC-32 that does not match its blob.
  std::string bad_crc = good;
  const auto pos = bad_crc.find("\"crc32\": ");
  ASSERT_NE(pos, std::string::npos) << good.substr(0, 400);
  auto last = bad_crc.find_first_not_of("0123456789", pos + 9) - 1;  // last digit of the CRC
  bad_crc[last] = static_cast<char>('0' + (bad_crc[last] - '0' + 1) % 10);
  write_text(dir_ / "bad_crc.json", bad_crc);
  write_text(dir_ / "truncated.json", good.substr(0, good.size() / 2));
  write_text(dir_ / "garbage.pb", "\xff\xff\xff garbage");
  auto r = expect_refusal("import '" + (dir_ / "bad_crc.json").string() + "'", 1, "CRC");
  for (const std::string name : {"truncated.json", "garbage.pb"}) {
    r = run("import '" + (dir_ / name).string() + "'");
    EXPECT_EQ(r.exit_code, 1) << name;
    EXPECT_NE(r.err.find("import"), std::string::npos) << name << ": " << r.err;
  }
  expect_refusal("import '" + (dir_ / "missing.json").string() + "'", 1, "cannot read");
  EXPECT_EQ(contents(), before);
  // A failed import into a new file creates no archive.
  r = run("import '" + (dir_ / "garbage.pb").string() + "'", (dir_ / "new.sqlite3").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "new.sqlite3"));
}

TEST_F(ArchiveCli, FilesThatAreNotOurArchive) {
  auto r = run("list", (dir_ / "missing.sqlite3").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("no archive at"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "missing.sqlite3"));

  write_text(dir_ / "text.sqlite3", std::string(4096, 'x'));
  r = run("list", (dir_ / "text.sqlite3").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("not an rs4sim archive"), std::string::npos) << r.err;

  const auto other = dir_ / "other.sqlite3";
  sql(other, "CREATE TABLE t(x)");
  r = run("verify", other.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("not an rs4sim archive"), std::string::npos) << r.err;

  sql(archive_, "PRAGMA user_version = 999");
  expect_refusal("list", 1, "newer rs4sim");
}

TEST_F(ArchiveCli, AnOlderSchemaIsReadAfterInitMigratesIt) {
  // The archive as the previous rs4sim left it (schema 4: no simulated time beside the wall
  // clock). A read-only command cannot migrate it: it says which command does, and that one
  // keeps every row.
  sql(archive_, "ALTER TABLE versions DROP COLUMN simulated_ms; PRAGMA user_version = 4");
  auto r = run("list");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("schema version 4 needs a migration"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("with: rs4sim archive init --archive '" + archive_.string() + "'"),
            std::string::npos)
      << r.err;
  r = run("init");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("ready (2 stations)"), std::string::npos) << r.out;
  r = run("history --address 4 --json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(parse_json(r.out).get_child("versions").size(), 2U);
}

TEST_F(ArchiveCli, LockedArchive) {
  // Another writer holds the lock beyond the busy timeout (5 s): restore gives up.
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(archive_.c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db, "BEGIN EXCLUSIVE", nullptr, nullptr, nullptr), SQLITE_OK);
  const auto r = run("restore 1");
  sqlite3_exec(db, "ROLLBACK", nullptr, nullptr, nullptr);
  sqlite3_close(db);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("locked"), std::string::npos) << r.err;
  EXPECT_EQ(parse_json(run("history --address 4 --json").out).get_child("versions").size(), 2U);
}

}  // namespace
}  // namespace rs4sim::app::testing
