// `rs4sim gsd` run as a process: the output an engineer types into a master, checked against the
// sources (CRC1 by a reference implementation written here from [IEC 61784-3-3 CRC1]) and the
// refusals of bad input.
#include "test_util.h"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>

namespace rs4sim::gsd {
namespace {

struct ProcessResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

ProcessResult run(const std::string& args) {
  const std::string command = std::string(RS4SIM_EXE) + " " + args + " 2>&1";
  ProcessResult r;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    r.output.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

std::uint16_t reference_crc1(std::initializer_list<std::uint8_t> bytes) {
  return testing::reference_crc1(std::vector<std::uint8_t>(bytes));
}

std::string crc_hex(std::uint16_t crc) {
  char b[8];
  std::snprintf(b, sizeof b, "%02X %02X", crc >> 8, crc & 0xFF);
  return b;
}

TEST(GsdCli, PrintsTheShippedGsd) {
  const ProcessResult r = run("gsd");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.output, testing::read_file(RS4SIM_GSD_SHIPPED));
}

TEST(GsdCli, WritesTheGsdToAFile) {
  const auto path = std::filesystem::temp_directory_path() / "rs4sim_cli_test_RSIM5234.gsd";
  std::filesystem::remove(path);
  const ProcessResult r = run("gsd --output " + path.string());
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(testing::read_file(path.string()), testing::read_file(RS4SIM_GSD_SHIPPED));
  std::filesystem::remove(path);
  EXPECT_NE(run("gsd --output /nonexistent-dir/x.gsd").exit_code, 0);
}

TEST(GsdCli, DefaultPrm) {
  const ProcessResult r = run("gsd --prm");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("Ident_Number: 0x5234\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("Chk_Cfg: C0 84 84\n"), std::string::npos) << r.output;
  // DPV1 status, F header, flags SIL2/2-byte CRC, src 1, dst 504, WD 10 ms, CRC1.
  const std::string crc = crc_hex(reference_crc1({0x14, 0x00, 0x00, 0x01, 0x01, 0xF8, 0x00, 0x0A}));
  EXPECT_NE(
      r.output.find("User_Prm_Data: 80 24 0B 0E 05 01 00 14 00 00 01 01 F8 00 0A " + crc + "\n"),
      std::string::npos)
      << r.output;
}

TEST(GsdCli, Address100Watchdog500Source2002) {
  const ProcessResult r = run("gsd --prm --address 100 --f-wd-time 500 --f-source-add 2002");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // F_Dest_Add = 500 + 100 = 600 = 0x0258 ([RS4 manual §4.5]).
  const std::string crc = crc_hex(reference_crc1({0x14, 0x00, 0x07, 0xD2, 0x02, 0x58, 0x01, 0xF4}));
  EXPECT_NE(
      r.output.find("User_Prm_Data: 80 24 0B 0E 05 01 00 14 00 07 D2 02 58 01 F4 " + crc + "\n"),
      std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("F_Dest_Add=600"), std::string::npos);
}

TEST(GsdCli, JsonOutput) {
  const ProcessResult r = run("gsd --prm --json --f-check-seqnr");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string crc = crc_hex(reference_crc1({0x15, 0x00, 0x00, 0x01, 0x01, 0xF8, 0x00, 0x0A}));
  EXPECT_NE(r.output.find("\"ident_number\": \"0x5234\""), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\"chk_cfg\": \"C0 84 84\""), std::string::npos);
  EXPECT_NE(r.output.find("\"user_prm_data\": \"80 24 0B 0E 05 01 00 15 00 00 01 01 F8 00 0A " +
                          crc + "\""),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("{\"name\": \"F_Check_SeqNr\", \"offset\": 7, \"value\": 1}"),
            std::string::npos);
}

TEST(GsdCli, RefusesOutOfRangeValues) {
  ProcessResult r = run("gsd --prm --f-wd-time 5");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("F_WD_Time = 5 is out of range 10..1000"), std::string::npos) << r.output;
  r = run("gsd --prm --f-source-add 65535");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("F_Source_Add = 65535 is out of range 1..65534"), std::string::npos)
      << r.output;
  r = run("gsd --prm --address 127");
  EXPECT_EQ(r.exit_code, 2);  // the parser's range check: a usage error
  EXPECT_NE(r.output.find("--address"), std::string::npos) << r.output;
  r = run("gsd --prm --set F_SIL=2");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("F_SIL is fixed at 1"), std::string::npos) << r.output;
  r = run("gsd --prm --set F_WD_Time=abc");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("'abc' is not a number"), std::string::npos) << r.output;
  r = run("gsd --json");
  EXPECT_EQ(r.exit_code, 2);
}

TEST(GsdCli, ForeignGsdFileAndModule) {
  const std::string file = std::string(RS4SIM_GSD_CORPUS) + "/modular_dpv1.gsd";
  ProcessResult r = run("gsd --prm --gsd " + file +
                        " --module 'DI 8' --module 'AI 2' --set Mode=5 --set Offset=-100");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("Ident_Number: 0xB756\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("Chk_Cfg: 10 51\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("User_Prm_Data: 80 00 00 55 AA 01 2C 9C\n"), std::string::npos)
      << r.output;
  r = run("gsd --prm --gsd " + file + " --module 'DI 9'");
  EXPECT_EQ(r.exit_code, 2);  // bad input
  EXPECT_NE(r.output.find("no module \"DI 9\""), std::string::npos) << r.output;
  r = run("gsd --prm --gsd /nonexistent.gsd");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("cannot read /nonexistent.gsd"), std::string::npos) << r.output;
}

TEST(GsdCli, MalformedGsdFileReportsFileAndLine) {
  const auto path = std::filesystem::temp_directory_path() / "rs4sim_cli_bad.gsd";
  {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    std::fputs("#Profibus_DP\nIdent_Number = 0x1234\nModule = \"x\" 0x10\n", f);
    std::fclose(f);
  }
  const ProcessResult r = run("gsd --prm --gsd " + path.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find(path.string() + ":3: Module is not closed (EndModule missing)"),
            std::string::npos)
      << r.output;
  std::filesystem::remove(path);
}

TEST(GsdCli, PresetModulesLeadTheSlotList) {
  const std::string file = std::string(RS4SIM_GSD_CORPUS) + "/preset_im153_style.gsd";
  const ProcessResult r = run("gsd --prm --gsd " + file + " --module 'DI 16' --module 'DO 8'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // The file's header comment: the three presets, then the user's modules.
  EXPECT_NE(r.output.find("Module: Config for Slot1 (slot 1, preset)\n"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("Module: DO 8 (slot 5)\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("Chk_Cfg: 04 00 00 AD C4 04 00 00 8B 41 04 00 00 8F C0 11 20\n"),
            std::string::npos)
      << r.output;
}

std::string write_temp(const std::string& name, const std::string& bytes) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f) {
    std::fwrite(bytes.data(), 1, bytes.size(), f);
    std::fclose(f);
  }
  return path.string();
}

TEST(GsdCli, CheckShowsWhatIsReadAndEveryWarning) {
  const std::string path = write_temp(
      "rs4sim_cli_check.gsd",
      "#Profibus_DP\nIdent_Number = 0x4224\n9.6_supp = 1\nMaxTsdr_9.6 = 60\n1.5M_supp = 1\n"
      "MaxTsdr_1.5M = 150\nModular_Station = 1\nMax_Input_Len = 249\nFIXPRESETMODULES = 1\n"
      "X_Vendor_Thing = 3\nModule = \"fixed\" 0x00\nPreset = 1\nEndModule\n"
      "Module = \"in   \" 0x10\nEndModule\n");
  const ProcessResult r = run("gsd check " + path);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const std::string& line : std::vector<std::string>{
           "Ident_Number: 0x4224\n",
           "Rates (MaxTsdr, bit times): 9.6k 60 1.5M 150\n",
           "Station: modular, Max_Module 1, Modul_Offset 0, FixPresetModules, DP-V0\n",
           "Max_Input_Len 244,",
           "  \"fixed\"  Cfg 00  in 0 out 0  preset  (line 11)\n",
           "  \"in   \"  Cfg 10  in 1 out 0  (line 14)\n",
           "Default configuration: slot 0 \"fixed\" (preset)\n  Chk_Cfg: 00\n",
           "Warnings (2):\n",
           path + ":8: Max_Input_Len = 249 is out of range 0..244; 244 taken",
           path + ":10: 'X_Vendor_Thing' is not a GSD keyword, line skipped",
       }) {
    EXPECT_NE(r.output.find(line), std::string::npos) << line << "\n" << r.output;
  }
  std::filesystem::remove(path);
}

TEST(GsdCli, CheckShowsTheFParameterDefaults) {
  const ProcessResult r = run("gsd check " + std::string(RS4SIM_GSD_CORPUS) + "/profisafe_v2.gsd");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // The file's header comment gives the 8 bytes; CRC1 over them from the reference here.
  const std::string crc = crc_hex(reference_crc1({0x08, 0x40, 0x00, 0x01, 0x00, 0x01, 0x00, 0x96}));
  EXPECT_NE(r.output.find("F-parameters of \"75x-661 4FDI\": 08 40 00 01 00 01 00 96 "),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("CRC1 over the defaults 0x" + crc.substr(0, 2) + crc.substr(3, 2)),
            std::string::npos)
      << r.output;
}

// Every part is found in the output.
void expect_parts(const std::string& output, const std::vector<std::string>& parts) {
  for (const std::string& part : parts) {
    EXPECT_NE(output.find(part), std::string::npos) << part << "\n" << output;
  }
}

// The project's F-module files (corpus/f_module_v1.gsd, f_module_v2.gsd) carry the F_Par_CRC
// two makers wrote into their GSD files for the same defaults: 0x783E (V1), 0xBB95 (V2).
TEST(GsdCli, CheckShowsTheFModulesOfV1AndV2) {
  const std::string corpus = std::string(RS4SIM_GSD_CORPUS);
  ProcessResult r = run("gsd check " + corpus + "/f_module_v1.gsd");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  expect_parts(r.output, {
           "F-module \"PROFIsafe v1.x Module\" (line 55): PROFIsafe V1, CRC2 2 bytes + "
           "consecutive number; F-inputs 4 bytes, F-outputs 4 bytes",
           "F-parameters of \"PROFIsafe v1.x Module\": 14 00 00 01 00 01 00 64 78 3E; F_Par_CRC "
           "in the file 0x783E, CRC1 over the defaults 0x783E (equal)\n",
           "    +6 7 \"F_WD_Time\" Unsigned16, default 100, range 10..10000\n",
           "    +0 2 \"F_SIL\" BitArea(2-3), default 1, range 1..1\n",
           "  F_ParamDescCRC 47103 (0xB7FF), F_IO_StructureDescCRC 9140 (0x23B4)\n"});
  r = run("gsd check " + corpus + "/f_module_v2.gsd");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  expect_parts(r.output, {
           "PROFIsafe V2, CRC2 3 bytes (virtual consecutive number); F-inputs 8 bytes, "
           "F-outputs 8 bytes",
           ": 08 40 00 01 00 01 00 96 BB 95; F_Par_CRC in the file 0xBB95, CRC1 over the "
           "defaults 0xBB95 (equal)\n  at byte 4 of the F-part (F_Ext_Module_Prm_Data_Len 14)"});
}

TEST(GsdCli, PrmShowsTheSafetyIoOfAPresetV2FModule) {
  const std::string file = std::string(RS4SIM_GSD_CORPUS) + "/f_module_v2.gsd";
  ProcessResult r = run("gsd --prm --gsd " + file + " --module 'AS-i 16 bytes in/out'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  expect_parts(r.output, {"F_Par_CRC (CRC1) of module 1: 0xBB95\n",
                          "F-module 1 (F-Link(PROFIsafe)): PROFIsafe V2, CRC2 3 bytes",
                          "  F-parameters at +7: 08 40 00 01 00 01 00 96 BB 95\n"});
  // A changed F_WD_Time (200 ms = 00 C8) gets its own CRC1, from the reference here.
  r = run("gsd --prm --json --gsd " + file + " --module 'AS-i 16 bytes in/out' --set F_WD_Time=200");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string crc = crc_hex(reference_crc1({0x08, 0x40, 0x00, 0x01, 0x00, 0x01, 0x00, 0xC8}));
  EXPECT_NE(r.output.find("\"f_par_crc\": [\"0x" + crc.substr(0, 2) + crc.substr(3, 2) + "\"]"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("{\"module\": 1, \"offset\": 7, \"version\": 2, \"crc2_bytes\": 3, "
                          "\"f_input_bytes\": 8, \"f_output_bytes\": 8}"),
            std::string::npos)
      << r.output;
}

TEST(GsdCli, AnFModuleWithoutFParametersIsRefusedWithFileLineAndExit2) {
  const std::string path = write_temp(
      "rs4sim_cli_f_no_prm.gsd",
      "#Profibus_DP\nIdent_Number = 0x4224\n12M_supp = 1\nMaxTsdr_12M = 800\n"
      "Module = \"F-DI\" 0xB4\nF_IO_StructureDescCRC = 1234\nEndModule\n");
  ProcessResult r = run("gsd check " + path);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(path + ":5: module \"F-DI\" is an F-module but has no F-parameter "
                                 "description"),
            std::string::npos)
      << r.output;
  r = run("gsd --prm --gsd " + path);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  std::filesystem::remove(path);
  const std::string range = write_temp(
      "rs4sim_cli_f_range.gsd",
      "#Profibus_DP\nIdent_Number = 0x4224\n12M_supp = 1\nMaxTsdr_12M = 800\n"
      "ExtUserPrmData = 1 \"F_WD_Time\"\nUnsigned16 0 0-100\nEndExtUserPrmData\n"
      "ExtUserPrmData = 2 \"F_Par_CRC\"\nUnsigned16 0 0-65535\nEndExtUserPrmData\n"
      "Module = \"F\" 0xB4\nF_Ext_Module_Prm_Data_Len = 10\n"
      "F_Ext_User_Prm_Data_Const(0) = 0x10,0,0,1,0,1\n"
      "F_Ext_User_Prm_Data_Ref(6) = 1\nF_Ext_User_Prm_Data_Ref(8) = 2\nEndModule\n");
  r = run("gsd check " + range);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(range + ":5: module \"F\": F_WD_Time default 0 is outside PROFIsafe's "
                                  "1..65535"),
            std::string::npos)
      << r.output;
  std::filesystem::remove(range);
}

TEST(GsdCli, CheckRefusesWhatIsNoGsdWithFileLineAndExit2) {
  const std::string garbage =
      write_temp("rs4sim_cli_garbage.gsd", std::string("\x7f\x45\x4c\x46\x02\x01\x00\x00\xff", 9));
  ProcessResult r = run("gsd check " + garbage);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(garbage + ":1: not a GSD: the first keyword line must be #Profibus_DP"),
            std::string::npos)
      << r.output;
  const std::string no_ident =
      write_temp("rs4sim_cli_no_ident.gsd", "#Profibus_DP\n12M_supp = 1\n");
  r = run("gsd check " + no_ident);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(no_ident + ": Ident_Number is missing"), std::string::npos) << r.output;
  r = run("gsd check /nonexistent.gsd");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = run("gsd check");
  EXPECT_EQ(r.exit_code, 2) << r.output;  // FILE is required
  std::filesystem::remove(garbage);
  std::filesystem::remove(no_ident);
}

}  // namespace
}  // namespace rs4sim::gsd
