// `rs4sim archive import` as a maintenance user meets it (issue: the same backup imported twice
// gave four versions and six sync-log rows, and an import moved the current set silently):
// what is already there is not added again, the current set moves only with --make-current,
// and the output says what happened.
#include "tests/app/archive_cli_fixture.h"

namespace rs4sim::app::testing {
namespace {

TEST_F(ArchiveCli, ImportingABackupTwiceAddsNothingAndSaysSo) {
  const auto file = dir_ / "backup.json";
  ASSERT_EQ(run("export '" + file.string() + "'").exit_code, 0);
  for (int round = 0; round < 2; ++round) {
    const auto r = run("import '" + file.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("added 0 versions (0 new sets), 3 already present; sync log 0 added, "
                         "1 already present"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("default/4: added 0, already present 2, current unchanged (current #2)"),
              std::string::npos)
        << r.out;
  }
  const auto history = parse_json(run("history --bus default --address 4 --json").out);
  EXPECT_EQ(history.get_child("versions").size(), 2u);
  EXPECT_EQ(history.get_child("sync_log").size(), 1u);
}

// A backup of the station's version 1 taken before version 2: imported into an archive
// where version 2 is current, it is recognised; into another archive with its own newer
// version, it is appended and the current set stays unless --make-current.
TEST_F(ArchiveCli, ImportKeepsTheCurrentSetUnlessMakeCurrent) {
  const auto file = dir_ / "backup.json";
  ASSERT_EQ(run("export '" + file.string() + "'").exit_code, 0);
  const auto other = (dir_ / "other.sqlite3").string();
  {
    auto a = storage::SqliteArchive::open(other).value();
    auto later = rs4::scanner::factory_default();
    later.response_steps = 3;
    store(*a, {"default", 4}, later, "1001", 1'764'600'000'000);
  }
  auto r = run("import '" + file.string() + "' --json", other);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto doc = parse_json(r.out);
  EXPECT_EQ(doc.get<int>("versions"), 3);
  EXPECT_EQ(at(doc.get_child("per_station"), 0).get<std::string>("current"), "current unchanged");
  EXPECT_EQ(at(doc.get_child("per_station"), 0).get<int>("current_version"), 1);
  r = run("import '" + file.string() + "' --make-current --json", other);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  doc = parse_json(r.out);
  EXPECT_EQ(doc.get<int>("versions"), 0);
  EXPECT_EQ(at(doc.get_child("per_station"), 0).get<std::string>("current"), "made current");
  EXPECT_EQ(at(doc.get_child("per_station"), 0).get<int>("current_version"), 3);
}

}  // namespace
}  // namespace rs4sim::app::testing
