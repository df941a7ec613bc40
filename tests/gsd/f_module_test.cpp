// PROFIsafe F-modules of a GSD (gsd/f_module.h). The known answers are two vendor facts, built
// into the project's own files corpus/f_module_v1.gsd and corpus/f_module_v2.gsd: a drive maker's
// "PROFIsafe v1.x Module" carries F_Par_CRC 0x783E over 14 00 00 01 00 01 00 64, an AS-i F-Link
// maker's "F-Link(PROFIsafe)" module 0xBB95 over 08 40 00 01 00 01 00 96 (each the CRC1
// [IEC 61784-3-3 CRC1] over the defaults, as the makers wrote it into their GSD files).
#include "gsd/f_module.h"
#include "gsd/interp.h"
#include "test_util.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace rs4sim::gsd {
namespace {

using Bytes = std::vector<std::uint8_t>;

Device load(const std::string& name) {
  auto d = parse(testing::corpus(name), name);
  EXPECT_TRUE(d) << (d ? "" : d.error().what());
  return d ? d.value() : Device{};
}

// version (1 or 2), CRC2 bytes, number bytes, F-input bytes, F-output bytes
std::vector<std::size_t> shape(const SafetyIoLayout& io) {
  return {io.version == profisafe::ProtocolVersion::kV1 ? 1U : 2U, io.crc2_bytes, io.number_bytes,
          io.f_input_bytes, io.f_output_bytes};
}

std::vector<std::string> field_names(const FModuleInfo& info) {
  std::vector<std::string> out;
  for (const auto& f : info.fields) out.push_back(f.param->name);
  return out;
}

TEST(GsdFModule, V1DriveModuleCarriesTheMakersCrc1) {
  const Device d = load("f_module_v1.gsd");
  const Module* m = d.find_module("PROFIsafe v1.x Module");
  ASSERT_NE(m, nullptr);
  ASSERT_TRUE(is_f_module(*m));
  EXPECT_FALSE(is_f_module(*d.find_module("Standard telegram 1, PZD-2/2")));
  auto info = describe_f_module(d, *m);
  ASSERT_TRUE(info) << info.error().what();
  const FModuleInfo& f = info.value();
  EXPECT_EQ(f.defaults.block, (Bytes{0x14, 0x00, 0x00, 0x01, 0x00, 0x01, 0x00, 0x64, 0x78, 0x3E}));
  EXPECT_EQ(f.defaults.offset, 0U);
  EXPECT_EQ(f.defaults.file_crc, 0x783E);
  EXPECT_EQ(f.defaults.crc1, 0x783E);
  // An independent CRC1 over the 8 bytes gives the maker's value too.
  EXPECT_EQ(testing::reference_crc1({0x14, 0x00, 0x00, 0x01, 0x00, 0x01, 0x00, 0x64}), 0x783E);
  EXPECT_EQ(f.parameters.sil, profisafe::Sil::kSil2);
  EXPECT_EQ(f.parameters.crc_length, profisafe::CrcLength::k2Byte);
  EXPECT_EQ(f.parameters.wd_time_ms, 100);
  // C0 87 87: 8 bytes each way = 4 F-data + status/control + consecutive number + CRC2 (2).
  EXPECT_EQ(shape(f.io), (std::vector<std::size_t>{1, 2, 1, 4, 4}));
  EXPECT_EQ(field_names(f), (std::vector<std::string>{"F_Check_SeqNr", "F_SIL", "F_CRC_Length",
                                                     "F_Par_Version", "F_Source_Add", "F_Dest_Add",
                                                     "F_WD_Time", "F_Par_CRC"}));
  EXPECT_EQ(f.fields[6].offset, 6U);
  EXPECT_EQ(f.fields[6].param->range_text(), "10..10000");
  EXPECT_EQ(m->f_param_desc_crc, 47103);
  EXPECT_EQ(m->f_io_structure_desc_crc, 9140);
}

TEST(GsdFModule, V2PresetModuleCarriesTheMakersCrc1) {
  const Device d = load("f_module_v2.gsd");
  const Module* m = d.find_module("F-Link(PROFIsafe)");
  ASSERT_NE(m, nullptr);
  EXPECT_TRUE(m->preset);
  auto info = describe_f_module(d, *m);
  ASSERT_TRUE(info) << info.error().what();
  const FModuleInfo& f = info.value();
  EXPECT_EQ(f.defaults.block, (Bytes{0x08, 0x40, 0x00, 0x01, 0x00, 0x01, 0x00, 0x96, 0xBB, 0x95}));
  EXPECT_EQ(f.defaults.offset, 4U);  // after the 4-byte header of the F-part
  EXPECT_EQ(f.defaults.file_crc, 48021);
  EXPECT_EQ(f.defaults.crc1, 0xBB95);
  EXPECT_EQ(f.parameters.sil, profisafe::Sil::kSil3);
  EXPECT_EQ(f.parameters.par_version, 1);
  // C0 8B 8B: 12 bytes each way = 8 F-data + status/control + CRC2 (3), no number sent.
  EXPECT_EQ(shape(f.io), (std::vector<std::size_t>{2, 3, 0, 8, 8}));
}

// The preset F-module leads the slot list; its block sits after DPV1_Status_1..3 and the F-part
// header, at User_Prm_Data byte 7, and configure() computes the same CRC1 the maker wrote.
TEST(GsdFModule, V2PresetBlockInTheStationsUserPrmData) {
  const Device d = load("f_module_v2.gsd");
  auto c = configure(d, {{"AS-i 16 bytes in/out"}, {}});
  ASSERT_TRUE(c) << c.error().what();
  ASSERT_EQ(c.value().f_parameters.size(), 1U);
  const FParameterBlock& b = c.value().f_parameters[0];
  EXPECT_EQ(b.module, 0U);
  EXPECT_EQ(b.offset, 7U);
  EXPECT_EQ(b.parameters.par_crc, 0xBB95);
  EXPECT_EQ(c.value().user_prm_data,
            (Bytes{0x80, 0x00, 0x00, 0x0E, 0x05, 0x00, 0x00, 0x08, 0x40, 0x00, 0x01, 0x00, 0x01,
                   0x00, 0x96, 0xBB, 0x95}));
  EXPECT_EQ(c.value().cfg, (Bytes{0xC0, 0x8B, 0x8B, 0xBF}));
}

// A 4-byte CRC2 (V2, F_CRC_Length 2) leaves one byte more of overhead.
TEST(GsdFModule, LayoutByVersionAndCrcLength) {
  Module m;
  m.name = "F";
  m.input_len = 12;
  m.output_len = 5;
  profisafe::FParameters p;
  p.par_version = 1;
  p.crc_length = profisafe::CrcLength::k4Byte;
  auto io = safety_io_layout(m, p);
  ASSERT_TRUE(io) << io.error().what();
  // 7 F-input bytes; an F-input module's outputs: control byte and CRC2 only.
  EXPECT_EQ(shape(io.value()), (std::vector<std::size_t>{2, 4, 0, 7, 0}));
  m.output_len = 4;
  io = safety_io_layout(m, p);
  ASSERT_FALSE(io);
  EXPECT_EQ(io.error().code, GsdError::kFParameterLayout);
  p.crc_length = profisafe::CrcLength::k2Byte;  // V2 never uses the 2-byte CRC2
  io = safety_io_layout(m, p);
  ASSERT_FALSE(io);
  EXPECT_NE(io.error().message.find("F_Par_Version 1 with F_CRC_Length 1"), std::string::npos)
      << io.error().message;
}

TEST(GsdFModule, ShippedRs4ModuleIsAV1FModuleWithOneByteEachWay) {
  auto d = parse(testing::read_file(RS4SIM_GSD_SHIPPED), "RSIM5234.gsd");
  ASSERT_TRUE(d) << d.error().what();
  auto info = describe_f_module(d.value(), d.value().modules[0]);
  ASSERT_TRUE(info) << info.error().what();
  // [RS4 manual §6.3]: V1, one byte each way.
  EXPECT_EQ(shape(info.value().io), (std::vector<std::size_t>{1, 2, 1, 1, 1}));
}

// Bad F-modules: the file and line of what is wrong.
struct BadCase {
  const char* title;
  std::string text;
  GsdError code;
  std::string what;
};

// An F-module's F-part with the given F_Par_Version and F_CRC_Length defaults and Cfg.
std::string f_file(const std::string& dest, int version, int crc_length, const std::string& cfg) {
  return testing::minimal(
      "ExtUserPrmData = 1 \"F_Dest_Add\"\nUnsigned16 " + dest +
      " 0-65535\nEndExtUserPrmData\n"                          // lines 5..7
      "ExtUserPrmData = 2 \"F_Par_CRC\"\nUnsigned16 0 0-65535\nEndExtUserPrmData\n"  // 8..10
      "Module = \"F\" " + cfg + "\n"                                                  // 11
      "F_Ext_Module_Prm_Data_Len = 10\nF_Ext_User_Prm_Data_Const(0) = " +
      std::to_string(crc_length << 4) + "," + std::to_string(version << 6) +
      ",0,1,0,1,0,100\nF_Ext_User_Prm_Data_Ref(4) = 1\nF_Ext_User_Prm_Data_Ref(8) = 2\n"
      "EndModule\n");
}

TEST(GsdFModule, BadFModulesNameFileAndLine) {
  const std::vector<BadCase> cases = {
      {"F_ParamDescCRC without F-part",
       testing::minimal("Module = \"F\" 0xB4\nF_ParamDescCRC = 5\nEndModule\n"),
       GsdError::kMissingKeyword,
       "f.gsd:5: module \"F\" is an F-module but has no F-parameter description "
       "(F_Ext_Module_Prm_Data_Len, F_Ext_User_Prm_Data_Ref)"},
      {"F-part of constants only",
       testing::minimal("Module = \"F\" 0xB4\nF_Ext_Module_Prm_Data_Len = 10\nEndModule\n"),
       GsdError::kMissingKeyword, "f.gsd:5: module \"F\" is an F-module but has no F-parameter"},
      {"F_Dest_Add default 0", f_file("0", 0, 1, "0xB4"), GsdError::kOutOfRange,
       "f.gsd:5: module \"F\": F_Dest_Add default 0 is outside PROFIsafe's 1..65534"},
      {"V1 with a 3-byte CRC2", f_file("1", 0, 0, "0xB4"), GsdError::kFParameterLayout,
       "f.gsd:11: module \"F\": F_Par_Version 0 with F_CRC_Length 0 is no PROFIsafe connection"},
      {"Cfg too short for a V1 PDU", f_file("1", 0, 1, "0xB2"), GsdError::kFParameterLayout,
       "f.gsd:11: module \"F\": inputs of 3 bytes (Cfg) hold no safety PDU of 4 bytes overhead"},
  };
  for (const auto& c : cases) {
    auto d = parse(c.text, "f.gsd");
    ASSERT_FALSE(d) << c.title;
    EXPECT_EQ(d.error().code, c.code) << c.title;
    EXPECT_NE(d.error().what().find(c.what), std::string::npos)
        << c.title << ": " << d.error().what();
  }
  EXPECT_TRUE(parse(f_file("1", 0, 1, "0xB4"), "f.gsd")) << "the same file, well formed";
}

}  // namespace
}  // namespace rs4sim::gsd
