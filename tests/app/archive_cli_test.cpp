// `rs4sim archive list|history|show|diff` on the fixture's archive (archive_cli_fixture.h):
// tables, --json documents parsed back, SVG pictures parsed as XML.
#include "archive_cli_fixture.h"

namespace rs4sim::app::testing {
namespace {

std::size_t panels(const ptree& svg) {
  std::size_t n = 0;
  for (const auto& [name, child] : svg.get_child("svg")) {
    if (name == "g" && child.get<std::string>("<xmlattr>.class", "") == "panel") ++n;
  }
  return n;
}

TEST_F(ArchiveCli, ListTable) {
  const auto r = run("list");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // 2025-12-01 14:00:00 UTC = 1764597600 s.
  EXPECT_NE(r.out.find("BUS      ADDR  DEVICE TYPE  SERIAL NUMBER  VERSIONS  CURRENT  NO  CRC32"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("line2       5  0x0004       2002                  1        3   1  0x"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("2025-12-01 14:00:00  upload"), std::string::npos) << r.out;
}

TEST_F(ArchiveCli, ListJson) {
  const auto r = run("list --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const ptree doc = parse_json(r.out);
  const auto& stations = doc.get_child("stations");
  ASSERT_EQ(stations.size(), 2U);
  EXPECT_EQ(at(stations, 0).get<std::string>("bus"), "default");
  EXPECT_EQ(at(stations, 0).get<int>("address"), 4);
  EXPECT_EQ(at(stations, 0).get<int>("versions"), 2);
  EXPECT_EQ(at(stations, 0).get<int>("current.id"), 2);
  EXPECT_EQ(at(stations, 0).get<std::string>("current.at"), "2025-12-01T13:00:00.000Z");
  EXPECT_EQ(at(stations, 1).get<std::string>("bus"), "line2");
  EXPECT_EQ(at(at(stations, 1).get_child("serial_numbers"), 0).get_value<std::string>(), "2002");
}

TEST_F(ArchiveCli, HistoryTableAndJson) {
  auto r = run("history --address 4");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("station default/4, 2 versions"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("   2  2025-12-01 13:00:00  upload  0x"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("8507  1001           current"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("parameter change  upload"), std::string::npos) << r.out;
  r = run("history --address 4 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const ptree doc = parse_json(r.out);
  EXPECT_EQ(doc.get<int>("current"), 2);
  EXPECT_EQ(doc.get_child("versions").size(), 2U);
  EXPECT_EQ(at(doc.get_child("versions"), 0).get<int>("number"), 1);
  EXPECT_EQ(at(doc.get_child("sync_log"), 0).get<int>("duration_ms"), 1500);
}

TEST_F(ArchiveCli, ShowDecodesTheSetAndDrawsIt) {
  const auto svg = dir_ / "v2.svg";
  auto r = run("show 2 --svg '" + svg.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("version 2 of station default/4 (number 2, current)"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("  pair 2 protective     1500.. 1850 mm on 529 segments"), std::string::npos)
      << r.out;
  const ptree picture = parse_xml(read_text(svg));
  EXPECT_EQ(panels(picture), 4U);
  EXPECT_NE(picture.get<std::string>("svg.title").find("version 2"), std::string::npos);

  r = run("show --address 4 --json");  // the current version
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const ptree doc = parse_json(r.out);
  EXPECT_EQ(doc.get<int>("version.id"), 2);
  EXPECT_TRUE(doc.get<bool>("current"));
  EXPECT_EQ(doc.get<int>("set.size"), 8507);
  EXPECT_EQ(at(doc.get_child("parameters.pairs"), 1).get<int>("protective.max_mm"), 1850);
  EXPECT_EQ(doc.get<int>("parameters.response_time_ms"), 80);
}

TEST_F(ArchiveCli, DiffByIdsText) {
  const auto r = run("diff 1 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("version 1 (default/4 #1, 0x"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\npair 2 protective: segments 100-140 changed, max +350 mm\n"),
            std::string::npos)
      << r.out;
}

TEST_F(ArchiveCli, DiffJsonAndPicture) {
  const auto svg = dir_ / "diff.svg";
  auto r = run("diff 1 2 --json --svg '" + svg.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const ptree doc = parse_json(r.out);
  EXPECT_EQ(doc.get<int>("old.id"), 1);
  EXPECT_EQ(doc.get<int>("new.id"), 2);
  EXPECT_FALSE(doc.get<bool>("diff.identical"));
  const auto& range = at(at(doc.get_child("diff.contours"), 0).get_child("ranges"), 0);
  EXPECT_EQ(range.get<int>("first"), 100);
  EXPECT_EQ(range.get<int>("last"), 140);
  EXPECT_EQ(range.get<int>("max_change_mm"), 350);
  const std::string text = read_text(svg);
  EXPECT_EQ(panels(parse_xml(text)), 4U);
  EXPECT_NE(text.find("class=\"old-protective\""), std::string::npos);
  EXPECT_NE(text.find(">version 1 protective</text>"), std::string::npos);
}

TEST_F(ArchiveCli, DiffDefaultsToTheCurrentVersion) {
  // --address alone: previous → current; one id: that version → its station's current.
  for (const std::string args : {"diff --address 4", "diff 1"}) {
    const auto r = run(args);
    ASSERT_EQ(r.exit_code, 0) << args << ": " << r.err;
    EXPECT_NE(r.out.find("pair 2 protective: segments 100-140 changed, max +350 mm"),
              std::string::npos)
        << args << ": " << r.out;
  }
  const auto r = run("diff 3");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("no differences"), std::string::npos) << r.out;
}

TEST_F(ArchiveCli, HelpOnEverySubcommand) {
  for (const std::string sub :
       {"list", "history", "show", "diff", "export", "import", "restore", "verify"}) {
    const auto r = run(sub + " --help");
    EXPECT_EQ(r.exit_code, 0) << sub;
    EXPECT_NE(r.out.find("--archive"), std::string::npos) << sub << ": " << r.out;
    EXPECT_NE(r.out.find("--json"), std::string::npos) << sub;
  }
}

}  // namespace
}  // namespace rs4sim::app::testing
