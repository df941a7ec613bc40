// Slave configuration from a GSD ([PROFIBUS GSD spec User_Prm_Data]
// [IEC 61158-6-3 Set_Prm, DPV1_Status]; [IEC 61784-3-3 F-Parameters, CRC1]). Known answers: CRC1
// values published in [IEC 61784-3-3 CRC1] (0xBB95 for the V2 default block, 0x5696 for the RS4
// manual's dialog values) and a bitwise reference CRC written here from the published description,
// independent of profisafe/.
#include "gsd/config.h"

#include "gsd/device_gsd.h"
#include "gsd/interp.h"
#include "test_util.h"

#include <gtest/gtest.h>

namespace rs4sim::gsd {
namespace {

// CRC-16, polynomial 0x4EAB, preset 0, MSB first, no reflection, no final XOR
// ([IEC 61158-6-3 DP-V0 services]).
std::uint16_t reference_crc1(const std::vector<std::uint8_t>& bytes) {
  std::uint16_t crc = 0;
  for (const auto b : bytes) {
    crc = static_cast<std::uint16_t>(crc ^ (b << 8));
    for (int i = 0; i < 8; ++i) {
      crc = (crc & 0x8000U) != 0 ? static_cast<std::uint16_t>((crc << 1) ^ 0x4EAB)
                                 : static_cast<std::uint16_t>(crc << 1);
    }
  }
  return crc;
}

const Device& rs4() {
  const auto& d = rs4sim_device();
  EXPECT_TRUE(d) << (d ? "" : d.error().what());
  return d.value();
}

SlaveSetup configure_ok(const Device& d, const ConfigRequest& r) {
  auto c = configure(d, r);
  EXPECT_TRUE(c) << (c ? "" : c.error().what());
  return c ? c.value() : SlaveSetup{};
}

TEST(GsdConfig, Rs4DefaultsGiveTheDocumentedSetPrmUserData) {
  const SlaveSetup c = configure_ok(rs4(), {});
  const std::vector<std::uint8_t> expected_without_crc{
      0x80,  // +0  DPV1_Status_1: DPV1_Enable
      0x24,  // +1  DPV1_Status_2: Enable_Diagnostic_Alarm (b5), Enable_Update_Alarm (b2)
      0x0B,  // +2  DPV1_Status_3: Prm_Structure (b3), Alarm_Mode 3 = 8 alarms
      0x0E,  // +3  structure length 14 (incl. itself)
      0x05,  // +4  structure type 5 = F-parameters
      0x01,  // +5  slot 1
      0x00,  // +6  reserved
      0x14,  // +7  F_Prm_Flag1: F_Check_SeqNr 0, F_Check_iPar 0, F_SIL 1 = SIL2, F_CRC_Length 1 = 2
             // byte
      0x00,  // +8  F_Prm_Flag2: F_Block_ID 0, F_Par_Version 0 = V1
      0x00, 0x01,  // +9  F_Source_Add 1
      0x01, 0xF8,  // +11 F_Dest_Add 504 = 500 + factory address 4
      0x00, 0x0A,  // +13 F_WD_Time 10 ms
  };
  ASSERT_EQ(c.user_prm_data.size(), 17U);
  EXPECT_EQ(std::vector<std::uint8_t>(c.user_prm_data.begin(), c.user_prm_data.begin() + 15),
            expected_without_crc);
  const std::uint16_t crc =
      reference_crc1({expected_without_crc.begin() + 7, expected_without_crc.end()});
  EXPECT_EQ(c.user_prm_data[15], crc >> 8);    // +15 F_Par_CRC high
  EXPECT_EQ(c.user_prm_data[16], crc & 0xFF);  // +16 F_Par_CRC low
  EXPECT_EQ(c.ident_number, 0x5234);
  EXPECT_TRUE(c.dpv1);
  EXPECT_EQ(c.dpv1_status, (std::array<std::uint8_t, 3>{0x80, 0x24, 0x0B}));
  EXPECT_EQ(c.cfg, (std::vector<std::uint8_t>{0xC0, 0x84, 0x84}));  // 5 out + 5 in, consistent
  EXPECT_EQ(c.input_len, 5U);
  EXPECT_EQ(c.output_len, 5U);
  ASSERT_EQ(c.f_parameters.size(), 1U);
  EXPECT_EQ(c.f_parameters[0].offset, 7U);
  EXPECT_EQ(c.f_parameters[0].parameters.par_crc, crc);
  EXPECT_EQ(c.f_parameters[0].parameters.dest_add, 504);
}

TEST(GsdConfig, ManualDialogValuesGiveThePublishedCrc1) {
  // [RS4 manual §6.2, §6.3]: src 2002, dst 604 (address 104), WD 500 → CRC1 0x5696.
  const SlaveSetup c =
      configure_ok(rs4(), {{}, {{"F_Source_Add", 2002}, {"F_Dest_Add", 604}, {"f_wd_time", 500}}});
  const std::vector<std::uint8_t> f_block{
      0x14, 0x00,  // +7  flags: SIL2, 2-byte CRC, V1
      0x07, 0xD2,  // +9  F_Source_Add 2002
      0x02, 0x5C,  // +11 F_Dest_Add 604
      0x01, 0xF4,  // +13 F_WD_Time 500
      0x56, 0x96,  // +15 F_Par_CRC 0x5696 ([IEC 61784-3-3 F-Parameters, CRC1])
  };
  EXPECT_EQ(std::vector<std::uint8_t>(c.user_prm_data.begin() + 7, c.user_prm_data.end()), f_block);
}

TEST(GsdConfig, CheckSeqNrSetsBit0OfFlag1) {
  const SlaveSetup c = configure_ok(rs4(), {{}, {{"F_Check_SeqNr", 1}}});
  EXPECT_EQ(c.user_prm_data[7], 0x15);
  EXPECT_EQ(c.user_prm_data[15] << 8 | c.user_prm_data[16],
            reference_crc1({0x15, 0x00, 0x00, 0x01, 0x01, 0xF8, 0x00, 0x0A}));
  EXPECT_TRUE(c.f_parameters[0].parameters.check_seqnr);
}

TEST(GsdConfig, OutOfRangeAndFixedValuesAreRefusedByName) {
  const struct {
    ParamOverride o;
    GsdError code;
    const char* message;
  } cases[] = {
      {{"F_WD_Time", 5}, GsdError::kOutOfRange, "F_WD_Time = 5 is out of range 10..1000"},
      {{"F_WD_Time", 1001}, GsdError::kOutOfRange, "F_WD_Time = 1001 is out of range 10..1000"},
      {{"F_Source_Add", 0}, GsdError::kOutOfRange, "F_Source_Add = 0 is out of range 1..65534"},
      {{"F_Source_Add", 65535},
       GsdError::kOutOfRange,
       "F_Source_Add = 65535 is out of range 1..65534"},
      {{"F_Dest_Add", 627}, GsdError::kOutOfRange, "F_Dest_Add = 627 is out of range 500..626"},
      {{"F_Check_SeqNr", 2}, GsdError::kOutOfRange, "F_Check_SeqNr = 2 is out of range 0..1"},
      {{"F_SIL", 2},
       GsdError::kNotChangeable,
       "F_SIL is fixed at 1 (Changeable = 0), cannot set 2"},
      {{"F_Par_Version", 1},
       GsdError::kNotChangeable,
       "F_Par_Version is fixed at 0 (Changeable = 0), cannot set 1"},
      {{"F_Par_CRC", 0x1234},
       GsdError::kNotChangeable,
       "F_Par_CRC is computed (CRC1 over the F-parameters) and cannot be set"},
      {{"F_Watchdog", 100},
       GsdError::kUnknownParameter,
       "no parameter \"F_Watchdog\" in this configuration (parameters: F_Block_ID, F_CRC_Length, "
       "F_Check_SeqNr, F_Check_iPar, F_Dest_Add, F_Par_CRC, F_Par_Version, F_SIL, F_Source_Add, "
       "F_WD_Time)"},
  };
  for (const auto& c : cases) {
    auto r = configure(rs4(), {{}, {c.o}});
    ASSERT_FALSE(r) << c.message;
    EXPECT_EQ(r.error().code, c.code);
    EXPECT_EQ(r.error().message, c.message);
  }
  // Setting a fixed parameter to its own value is not an error.
  EXPECT_TRUE(configure(rs4(), {{}, {{"F_SIL", 1}}}));
}

TEST(GsdConfig, ModuleChoiceIsChecked) {
  auto wrong = configure(rs4(), {{"DI 8"}, {}});
  ASSERT_FALSE(wrong);
  EXPECT_EQ(wrong.error().code, GsdError::kUnknownModule);
  EXPECT_EQ(wrong.error().message,
            "no module \"DI 8\" in the GSD (modules: \"RS4/PROFIsafe F-I/O (1 byte)\")");
  auto two =
      configure(rs4(), {{std::string(kRs4simModuleName), std::string(kRs4simModuleName)}, {}});
  ASSERT_FALSE(two);
  EXPECT_EQ(two.error().code, GsdError::kModuleCount);
  EXPECT_TRUE(configure(rs4(), {{"rs4/profisafe f-i/o (1 byte)"}, {}}));
}

TEST(GsdConfig, ProfisafeV2DefaultBlockGivesThePublishedCrc1) {
  auto d = parse(testing::corpus("profisafe_v2.gsd"), "profisafe_v2.gsd");
  ASSERT_TRUE(d) << d.error().what();
  const SlaveSetup c = configure_ok(d.value(), {{"75x-661 4FDI", "empty slot"}, {}});
  const std::vector<std::uint8_t> expected{
      0x80, 0x00, 0x08,        // +0  DPV1_Status_1..3 (global const)
      0x03, 0x00, 0x00,        // +3  module 1 Ext_Module_Prm_Data (3 bytes)
      0x0E, 0x05, 0x01, 0x00,  // +6  F block header, slot = [SlotNumber] default 1
      0x08,                    // +10 F_Prm_Flag1: F_SIL 2 = SIL3, F_CRC_Length 0 = 3 byte
      0x40,                    // +11 F_Prm_Flag2: F_Par_Version 1 = V2
      0x00, 0x01,              // +12 F_Source_Add 1
      0x00, 0x01,              // +14 F_Dest_Add 1
      0x00, 0x96,              // +16 F_WD_Time 150
      0xBB, 0x95,              // +18 F_Par_CRC 48021 ([IEC 61784-3-3 CRC1], first vector)
  };
  EXPECT_EQ(c.user_prm_data, expected);
  EXPECT_EQ(c.cfg, (std::vector<std::uint8_t>{0xC4, 0x84, 0x84, 0x05, 0x0A, 0x05, 0x0A, 0x00}));
  EXPECT_EQ(c.f_parameters[0].offset, 10U);
  EXPECT_EQ(c.f_parameters[0].module, 0U);
}

TEST(GsdConfig, ModularStationWithBitsWordsAndSignedValues) {
  auto d = parse(testing::corpus("modular_dpv1.gsd"), "modular_dpv1.gsd");
  ASSERT_TRUE(d) << d.error().what();
  const SlaveSetup c =
      configure_ok(d.value(), {{"DI 8", "AI 2", "DO 16 consistent"},
                               {{"Filter time", 564}, {"Offset", -100}, {"Mode", 5}}});
  const std::vector<std::uint8_t> expected{
      0x80, 0x00, 0x00,  // +0 DPV1_Status_1..3
      0x55,        // +3 const 0x01 | Diagnosis Bit(2)=1 → 0x05 | Mode BitArea(4-6)=5 → 0x55
      0xAA,        // +4 module "AI 2": const
      0x02, 0x34,  // +5 Filter time Unsigned16 564 = 0x0234, big-endian
      0x9C,        // +7 Offset Signed8 -100 (two's complement)
  };
  EXPECT_EQ(c.user_prm_data, expected);
  EXPECT_EQ(c.cfg, (std::vector<std::uint8_t>{0x10, 0x51, 0xA1}));
  EXPECT_EQ(c.input_len, 1U + 4U);
  EXPECT_EQ(c.output_len, 2U);
  EXPECT_TRUE(c.f_parameters.empty());
  auto bad = configure(d.value(), {{"DI 8"}, {{"Mode", 2}}});
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().message, "Mode = 2 is out of range 0, 1, 3, 5");
  auto none = configure(d.value(), {});
  ASSERT_FALSE(none);
  EXPECT_EQ(
      none.error().message,
      "choose the module(s) to configure (modules: \"DI 8\", \"AI 2\", \"DO 16 consistent\")");
  std::vector<std::string> five(5, "DI 8");
  auto many = configure(d.value(), {five, {}});
  ASSERT_FALSE(many);
  EXPECT_EQ(many.error().message, "a modular station takes 1..4 modules (Max_Module), got 5");
}

TEST(GsdConfig, TotalUserPrmDataRespectsMaxUserPrmDataLen) {
  auto d = parse(testing::minimal("Modular_Station = 1\nMax_Module = 3\nMax_User_Prm_Data_Len = 4\n"
                                  "Module = \"P\" 0x10\nExt_Module_Prm_Data_Len = 2\nEndModule\n"),
                 "p.gsd");
  ASSERT_TRUE(d) << d.error().what();
  EXPECT_TRUE(configure(d.value(), {{"P", "P"}, {}}));
  auto r = configure(d.value(), {{"P", "P", "P"}, {}});
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().code, GsdError::kPrmTooLong);
  EXPECT_EQ(r.error().message, "User_Prm_Data is 6 bytes, more than 4");
}

}  // namespace
}  // namespace rs4sim::gsd
