// `rs4sim archive restore` and `import` refuse to make current a stored RS4 set whose
// protective field has segments of 0 mm, with the count, unless --allow-partial-field says
// it on purpose (docs/param.md "Partial protective fields").
#include "tests/app/archive_cli_fixture.h"

namespace rs4sim::app::testing {
namespace {

// Pair 1's protective field with segments 0..99 at 0 mm: 100 of 529 unset.
rs4::scanner::ParameterSet partial_set() {
  auto set = rs4::scanner::factory_default();
  for (std::size_t n = 0; n < 100; ++n) set.pairs[0].protective_mm[n] = 0;
  return set;
}

TEST_F(ArchiveCli, RestoreRefusesAPartialProtectiveFieldUnlessAllowPartialField) {
  {
    auto a = storage::SqliteArchive::open(archive_).value();
    store(*a, {"default", 4}, partial_set(), "1001", 1'764'598'000'000);        // version 4
    store(*a, {"default", 4}, rs4::scanner::factory_default(), "1001", 1'764'599'000'000);
  }
  auto r = run("restore 4");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("restore 4: field pair 1: 100 of 529 segments"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("--allow-partial-field"), std::string::npos) << r.err;
  EXPECT_EQ(run("history --address 4 --json").out.find("\"restored_from\": 4"),
            std::string::npos);  // nothing stored

  r = run("restore 4 --allow-partial-field --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(parse_json(r.out).get<int>("version.restored_from"), 4);
}

TEST_F(ArchiveCli, ImportRefusesAPartialProtectiveFieldUnlessAllowPartialField) {
  const auto source = (dir_ / "partial.sqlite3").string();
  {
    auto a = storage::SqliteArchive::open(source).value();
    store(*a, {"default", 4}, partial_set(), "1001", 1'764'598'000'000);
  }
  const auto backup = (dir_ / "partial.json").string();
  ASSERT_EQ(run("export " + backup, source).exit_code, 0);
  const auto target = dir_ / "new.sqlite3";
  auto r = run("import " + backup, target.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("field pair 1: 100 of 529 segments"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--allow-partial-field"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(target));  // refused before the archive is opened

  r = run("import " + backup + " --allow-partial-field", target.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(run("list", target.string()).out.find("default     4"), std::string::npos);
}

}  // namespace
}  // namespace rs4sim::app::testing
