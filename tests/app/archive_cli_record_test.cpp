// What maintenance records, from the command line (docs/archive-cli.md): `archive note`,
// `restore --user`, who and where in `history`, `list --site/--line`, and `archive watch`
// seeing a version another process stores.
#include "app/runtime/author.h"
#include "tests/app/archive_cli_fixture.h"

#include <chrono>
#include <thread>

namespace rs4sim::app::testing {
namespace {

TEST_F(ArchiveCli, NoteReplacesAVersionsComment) {
  auto r = run("note 2 'checked by QA after the retrofit'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "version 2 (default/4 #2): note \"checked by QA after the retrofit\"\n");
  r = run("history --address 4 --json");
  const auto versions = parse_json(r.out).get_child("versions");
  EXPECT_EQ(at(versions, 1).get<std::string>("note"), "checked by QA after the retrofit");
  EXPECT_EQ(at(versions, 0).get<std::string>("note"), "");
  EXPECT_EQ(run("note 2 ''").out, "version 2 (default/4 #2): note cleared\n");
}

TEST_F(ArchiveCli, NoteRefusesWhatItCannotStore) {
  const auto before = contents();
  auto r = expect_refusal("note 99 'x'", 1, "version 99");
  expect_refusal("note 2 \"$(printf 'bad \\377')\"", 2, "archive note: note: byte 4 is not UTF-8");
  r = run("note 2");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(contents(), before);
}

TEST_F(ArchiveCli, RestoreRecordsWhoAndWhere) {
  auto r = run("restore 1 --user qa-engineer --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto doc = parse_json(r.out);
  EXPECT_EQ(doc.get<std::string>("version.user"), "qa-engineer");
  EXPECT_EQ(doc.get<std::string>("version.host"), host_name());
  EXPECT_FALSE(host_name().empty());
  r = run("history --address 4");
  const auto row = r.out.find("current, pending download, restores 1");
  ASSERT_NE(row, std::string::npos) << r.out;
  const auto line = r.out.substr(row, r.out.find('\n', row) - row);
  EXPECT_TRUE(line.ends_with("  qa-engineer@" + host_name())) << line;
  // Without --user: the OS user.
  doc = parse_json(run("restore 2 --json").out);
  EXPECT_EQ(doc.get<std::string>("version.user"), os_user());
  EXPECT_FALSE(os_user().empty());
}

TEST_F(ArchiveCli, ListShowsAndFiltersBySiteAndLine) {
  {
    auto a = storage::SqliteArchive::open(archive_).value();
    const auto blob = rs4::scanner::encode(rs4::scanner::factory_default());
    storage::StoreRequest r;
    r.station = {"line2", 5};
    r.blob = blob;
    r.crc32 = rs4::scanner::checksum(rs4::scanner::factory_default());
    r.site = "Hamburg";
    r.line = "Press line 2";
    ASSERT_TRUE(a->store(r));
  }
  auto r = run("list --site Hamburg");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find("default"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Hamburg  Press line 2"), std::string::npos) << r.out;
  r = run("list --site Hamburg --line 'Press line 2' --json");
  const auto stations = parse_json(r.out).get_child("stations");
  ASSERT_EQ(stations.size(), 1u);
  EXPECT_EQ(at(stations, 0).get<std::string>("site"), "Hamburg");
  EXPECT_EQ(at(stations, 0).get<int>("address"), 5);
  EXPECT_NE(run("list --site Bremen").out.find("with that site and line"), std::string::npos);
  EXPECT_EQ(run("list").out.find("no stations"), std::string::npos);  // no filter: all
}

TEST_F(ArchiveCli, WatchFromAnIdPrintsTheVersionsAfterItInIdOrder) {
  auto r = run("watch --after 1 --count 2 --timeout 20");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto two = r.out.find("default/4 #2  id 2  upload");
  const auto three = r.out.find("line2/5 #1  id 3  upload");
  EXPECT_NE(two, std::string::npos) << r.out;
  EXPECT_NE(three, std::string::npos) << r.out;
  EXPECT_LT(two, three);
  EXPECT_EQ(r.out.find("id 1 "), std::string::npos) << r.out;
}

// A second process stores (archive restore) while the watch waits: the watch prints it.
TEST_F(ArchiveCli, WatchSeesAVersionAnotherProcessStores) {
  const auto out = dir_ / "watch.txt";
  const std::string watch = std::string(RS4SIM_EXE) + " archive watch --count 1 --timeout 30 " +
                            "--archive '" + archive_.string() + "' >'" + out.string() +
                            "' 2>&1 &";
  ASSERT_EQ(std::system(watch.c_str()), 0);
  const auto wait_for = [&](const std::string& what) {
    std::string text;
    for (int i = 0; i < 300 && text.find(what) == std::string::npos; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      text = read_text(out);
    }
    return text;
  };
  // "watching ..." comes once the feed has read where it starts: a version stored after it
  // is new to the watch.
  auto text = wait_for("watching " + archive_.string());
  ASSERT_NE(text.find("watching "), std::string::npos) << text;
  auto r = run("restore 2 --note 'seen by the watch' --user qa");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  text = wait_for("seen by the watch");
  EXPECT_NE(text.find("default/4 #3  id 4  restore  0x"), std::string::npos) << text;
  EXPECT_NE(text.find("pending download  by qa@" + host_name() + ": seen by the watch"),
            std::string::npos)
      << text;
}

TEST_F(ArchiveCli, WatchTimesOutWithExit1AndRefusesATimeoutWithoutCount) {
  expect_refusal("watch --count 1 --timeout 0.3", 1, "0 of 1 versions within 0.3 s");
  expect_refusal("watch --timeout 1", 2, "--timeout needs --count");
}

}  // namespace
}  // namespace rs4sim::app::testing
