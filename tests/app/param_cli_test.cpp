// `rs4sim param get|set|diff` run as a process (docs/param.md) on set files in a temporary
// directory and on the archive of archive_cli_fixture.h. The expected sets are built by
// hand; an invalid document or a wrong password must leave the file's bytes untouched.
#include "archive_cli_fixture.h"
#include "rs4/param_doc/parameter_document.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <vector>

namespace rs4sim::app::testing {
namespace {

using rs4::scanner::ParameterSet;

class ParamCli : public ArchiveCli {
 protected:
  std::string write_set(const std::string& name, const ParameterSet& set) const {
    const auto bytes = rs4::scanner::encode(set);
    write_text(dir_ / name, std::string(bytes.begin(), bytes.end()));
    return (dir_ / name).string();
  }
  std::string write_doc(const std::string& name, const std::string& text) const {
    write_text(dir_ / name, text);
    return (dir_ / name).string();
  }
  CliResult param(const std::string& args) const { return run_rs4sim("param " + args); }
  static ParameterSet protected_set() {
    ParameterSet set = rs4::scanner::factory_default();
    set.passwords[0] = {'R', 'O', 'D', '4', 'L', 'E', 0xFF, 0xFF};
    return set;
  }
  // A set file of format 1 (the encoding alone), as write_set() writes it.
  static std::string raw(const ParameterSet& set) {
    const auto bytes = rs4::scanner::encode(set);
    return {bytes.begin(), bytes.end()};
  }
  // The set file `param set` writes (format 2, docs/param.md "Set files"): the encoding,
  // "RS4F", 02, then zlib's CRC-32 of all that, big-endian.
  static std::string encoded(const ParameterSet& set) {
    const auto bytes = rs4::scanner::encode(set);
    std::string file(bytes.begin(), bytes.end());
    file += "RS4F\x02";
    const auto crc = crc32(0L, reinterpret_cast<const Bytef*>(file.data()),
                           static_cast<uInt>(file.size()));
    for (const int shift : {24, 16, 8, 0}) file += static_cast<char>((crc >> shift) & 0xFF);
    return file;
  }
};

TEST_F(ParamCli, GetPrintsTheDocumentOfASetFile) {
  const auto file = write_set("set.bin", protected_set());
  const auto r = param("get --file " + file);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, rs4::param_doc::to_document(protected_set()));
  EXPECT_EQ(r.out.find("ROD4"), std::string::npos);
}

TEST_F(ParamCli, GetReadsTheStationsCurrentVersionFromTheArchive) {
  const auto r = param("get --address 4 --archive " + archive_.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto expected = raised_pair2();
  expected.identity.serial_number = 1001;  // the fixture's device
  EXPECT_EQ(r.out, rs4::param_doc::to_document(expected));
}

TEST_F(ParamCli, GetNeedsExactlyOneSource) {
  EXPECT_EQ(param("get").exit_code, 2);
  EXPECT_EQ(param("get --file a --address 4").exit_code, 2);
}

TEST_F(ParamCli, SetWritesTheValidatedSetWithThePassword) {
  const auto file = write_set("set.bin", protected_set());
  const auto doc = write_doc("doc.json", R"({"format": 1, "response_time_ms": 160})");
  const auto r = param("set " + doc + " --file " + file + " --password ROD4LE");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("response_time_ms: 80 -> 160"), std::string::npos) << r.out;
  ParameterSet expected = protected_set();
  expected.response_steps = 2;  // 80 + 2·40 ms
  EXPECT_EQ(read_text(file), encoded(expected));
}

// Issue: one run for segments 100..140 left the other 529 - 41 = 488 segments of pair 2's
// protective field at 0 mm (no field). Refused with that count unless said on purpose
// (docs/param.md "Partial protective fields").
TEST_F(ParamCli, SetRefusesAPartialProtectiveFieldUnlessAllowPartialField) {
  const auto file = write_set("set.bin", protected_set());
  const auto doc = write_doc("doc.json", R"({"format": 1, "pairs": {"2": {"protective": )"
                                         R"({"runs": [{"from": 100, "to": 140, "mm": 1850}]}}}})");
  auto r = param("set " + doc + " --file " + file + " --password ROD4LE");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("$.pairs.2.protective.runs: 488 of 529 segments"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("allow_partial_field"), std::string::npos) << r.err;
  EXPECT_EQ(read_text(file), raw(protected_set()));  // nothing changed

  r = param("set " + doc + " --file " + file + " --password ROD4LE --allow-partial-field");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ParameterSet expected = protected_set();
  expected.pairs[1].protective_mm.fill(0);
  for (std::size_t n = 100; n <= 140; ++n) expected.pairs[1].protective_mm[n] = 1850;
  EXPECT_EQ(read_text(file), encoded(expected));
}

TEST_F(ParamCli, WrongPasswordChangesNothing) {
  const auto file = write_set("set.bin", protected_set());
  const auto doc = write_doc("doc.json", R"({"format": 1, "response_time_ms": 160})");
  for (const char* password : {"", " --password ROD4", " --password rod4le"}) {
    const auto r = param("set " + doc + " --file " + file + password);
    EXPECT_EQ(r.exit_code, 1) << password;
    EXPECT_NE(r.err.find("wrong password"), std::string::npos) << r.err;
  }
  EXPECT_EQ(read_text(file), raw(protected_set()));
}

TEST_F(ParamCli, InvalidDocumentNamesThePathAndChangesNothing) {
  const auto file = write_set("set.bin", protected_set());
  const auto doc = write_doc(
      "doc.json",
      R"({"format": 1, "pairs": {"3": {"protective": {"runs": [{"from": 0, "to": 528, "mm": 4200}]}}}})");
  const auto r = param("set " + doc + " --file " + file + " --password ROD4LE");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("$.pairs.3.protective.runs[0].mm: 4200 is outside 0..4000 mm"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("nothing changed"), std::string::npos);
  EXPECT_EQ(read_text(file), raw(protected_set()));
}

TEST_F(ParamCli, AFormat1FileLoadsWithAWarningAndIsWrittenBackWithItsChecksum) {
  const auto file = write_set("set.bin", protected_set());
  const auto got = param("get --file " + file);
  ASSERT_EQ(got.exit_code, 0) << got.err;
  EXPECT_NE(got.err.find("warning: " + file + ": a set file of format 1 carries no checksum"),
            std::string::npos)
      << got.err;
  const auto doc = write_doc("doc.json", R"({"format": 1, "start_pair": 2})");
  ASSERT_EQ(param("set " + doc + " --file " + file + " --password ROD4LE").exit_code, 0);
  ParameterSet expected = protected_set();
  expected.start_pair = 2;
  EXPECT_EQ(read_text(file), encoded(expected));
  const auto again = param("get --file " + file);
  EXPECT_EQ(again.exit_code, 0);
  EXPECT_EQ(again.err, "");  // format 2: no warning
}

TEST_F(ParamCli, ADamagedSetFileIsRefusedByEveryCommandWithTheReason) {
  std::string bytes = encoded(protected_set());
  bytes[1000] = static_cast<char>(bytes[1000] ^ 0x10);  // a distance of pair 1's contours
  write_text(dir_ / "damaged.bin", bytes);
  const auto file = (dir_ / "damaged.bin").string();
  const auto doc = write_doc("doc.json", R"({"format": 1, "start_pair": 2})");
  for (const std::string& args : {"get --file " + file,
                                  "set " + doc + " --file " + file + " --password ROD4LE",
                                  "diff " + file + " " + file}) {
    const auto r = param(args);
    EXPECT_EQ(r.exit_code, 1) << args;
    EXPECT_NE(r.err.find(file + ": not an RS4 parameter set file: damaged: its CRC-32 says"),
              std::string::npos)
        << args << ": " << r.err;
  }
  EXPECT_EQ(read_text(file), bytes);  // nothing written
}

TEST_F(ParamCli, DryRunAndUsageErrors) {
  const auto file = write_set("set.bin", rs4::scanner::factory_default());
  const auto doc = write_doc("doc.json", R"({"format": 1, "start_pair": 2})");
  EXPECT_EQ(param("set " + doc + " --file " + file).exit_code, 1);  // factory: "ROD4LE"
  const auto r = param("set " + doc + " --file " + file + " --password ROD4LE --dry-run --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto tree = parse_json(r.out);
  EXPECT_EQ(tree.get<std::string>("written"), "false");
  EXPECT_EQ(read_text(file), raw(rs4::scanner::factory_default()));
  EXPECT_EQ(param("set --file " + file).exit_code, 2);  // no document
  EXPECT_EQ(param("set " + doc).exit_code, 2);          // no target
  EXPECT_EQ(param("set " + doc + " --file " + file + " --password 123456789").exit_code, 2);
  EXPECT_EQ(param("diff " + file).exit_code, 2);  // one operand
}

TEST_F(ParamCli, DiffOfTwoFilesAndOfADocumentAgainstAFile) {
  const auto old_file = write_set("old.bin", protected_set());
  ParameterSet changed = protected_set();
  changed.restart_mode = rs4::scanner::RestartMode::kAutomatic;
  for (std::size_t n = 100; n <= 140; ++n) changed.pairs[1].protective_mm[n] = 1850;
  const auto new_file = write_set("new.bin", changed);
  const auto r = param("diff " + old_file + " " + new_file + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out,
            R"({"identical":false,"identity":[],"options":[{"field":"restart_mode",)"
            R"("old":"start_restart_interlock","new":"automatic"}],"passwords_changed":[],)"
            R"("contours":[{"pair":2,"contour":"protective","ranges":[{"first":100,"last":140,)"
            R"("max_change_mm":350}]}]})"
            "\n");
  // A document knows neither passwords nor identity: they are not compared.
  const auto doc = write_doc("new.json", rs4::param_doc::to_document(changed));
  const auto same = param("diff " + doc + " " + new_file);
  ASSERT_EQ(same.exit_code, 0) << same.err;
  EXPECT_EQ(same.out, "no differences\n");
}

}  // namespace
}  // namespace rs4sim::app::testing
