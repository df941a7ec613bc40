// The malformed-GSD suite, meaning stage: every error names file:line, the offending
// statement and what is wrong with it.
#include "gsd/interp.h"
#include "test_util.h"

#include <gtest/gtest.h>

namespace rs4sim::gsd {
namespace {

using testing::minimal;

struct Case {
  const char* title;
  std::string text;
  GsdError code;
  std::string what;
};

// Line numbers: minimal() takes lines 1..4, the case's text starts on line 5.
const std::vector<Case>& cases() {
  static const std::vector<Case> kCases = {
      {"ident missing", "#Profibus_DP\n12M_supp = 1\nMaxTsdr_12M = 800\n",
       GsdError::kMissingKeyword, "m.gsd: Ident_Number is missing"},
      {"ident too big", "#Profibus_DP\nIdent_Number = 0x12345\n", GsdError::kOutOfRange,
       "m.gsd:2: Ident_Number = 74565 is out of range 0..65535: `Ident_Number = 0x12345`"},
      {"ident is a string", "#Profibus_DP\nIdent_Number = \"0x1234\"\n", GsdError::kBadValue,
       "m.gsd:2: Ident_Number expects one number: `Ident_Number = \"0x1234\"`"},
      {"no baud rate", "#Profibus_DP\nIdent_Number = 1\n", GsdError::kMissingKeyword,
       "m.gsd: no baud rate is supported (<rate>_supp = 1)"},
      {"const byte > 255", minimal("Ext_User_Prm_Data_Const(0) = 0x100\n"), GsdError::kOutOfRange,
       "m.gsd:5: Ext_User_Prm_Data_Const: byte value 256 is out of range 0..255: "
       "`Ext_User_Prm_Data_Const(0) = 0x100`"},
      {"const without offset", minimal("Ext_User_Prm_Data_Const = 1\n"), GsdError::kBadValue,
       "m.gsd:5: Ext_User_Prm_Data_Const expects one number in (…): `Ext_User_Prm_Data_Const = 1`"},
      {"ref to nothing", minimal("Ext_User_Prm_Data_Ref(0) = 9\n"), GsdError::kUnknownReference,
       "m.gsd:5: global User_Prm_Data: no ExtUserPrmData 9: `Ext_User_Prm_Data_Ref(0) = 9`"},
      {"global longer than max",
       minimal("Max_User_Prm_Data_Len = 2\nExt_User_Prm_Data_Const(0) = 1,2,3\n"),
       GsdError::kPrmTooLong,
       "m.gsd:6: global User_Prm_Data is 3 bytes, more than the maximum 2: "
       "`Ext_User_Prm_Data_Const(0) = 1,2,3`"},
      {"legacy data longer than its length",
       minimal("User_Prm_Data_Len = 1\nUser_Prm_Data = 1,2\n"), GsdError::kOutOfRange,
       "m.gsd:6: global User_Prm_Data: constant bytes end at byte 2, beyond the length 1: "
       "`User_Prm_Data = 1,2`"},
      {"DPV1 without status bytes", minimal("DPV1_Slave = 1\n"), GsdError::kMissingKeyword,
       "m.gsd: DPV1_Slave = 1 but User_Prm_Data does not hold the 3 DPV1_Status bytes"},
      {"param without type", minimal("ExtUserPrmData = 1 \"A\"\nEndExtUserPrmData\n"),
       GsdError::kMissingKeyword,
       "m.gsd:5: ExtUserPrmData 1 has no type line (Bit, BitArea, Unsigned8, …): `ExtUserPrmData = "
       "1 \"A\"`"},
      {"param without name", minimal("ExtUserPrmData = 1\nBit(0) 0 0-1\nEndExtUserPrmData\n"),
       GsdError::kBadValue,
       "m.gsd:5: ExtUserPrmData expects = <number> \"name\": `ExtUserPrmData = 1`"},
      {"param defined twice",
       minimal("ExtUserPrmData = 1 \"A\"\nBit(0) 0 0-1\nEndExtUserPrmData\n"
               "ExtUserPrmData = 1 \"B\"\nBit(1) 0 0-1\nEndExtUserPrmData\n"),
       GsdError::kDuplicate,
       "m.gsd:8: ExtUserPrmData 1 already defined at line 5: `ExtUserPrmData = 1 \"B\"`"},
      {"Bit(8)", minimal("ExtUserPrmData = 1 \"A\"\nBit(8) 0 0-1\nEndExtUserPrmData\n"),
       GsdError::kOutOfRange, "m.gsd:6: Bit(8) is out of range 0..7: `Bit(8) 0 0-1`"},
      {"BitArea reversed",
       minimal("ExtUserPrmData = 1 \"A\"\nBitArea(5-2) 0 0-1\nEndExtUserPrmData\n"),
       GsdError::kOutOfRange,
       "m.gsd:6: BitArea(5-2) must lie within bits 0..7, first <= last: `BitArea(5-2) 0 0-1`"},
      {"range does not fit BitArea",
       minimal("ExtUserPrmData = 1 \"A\"\nBitArea(0-1) 0 0-4\nEndExtUserPrmData\n"),
       GsdError::kOutOfRange,
       "m.gsd:6: allowed values 0..4 do not fit BitArea (0..3): `BitArea(0-1) 0 0-4`"},
      {"range does not fit Unsigned8",
       minimal("ExtUserPrmData = 1 \"A\"\nUnsigned8 0 0-256\nEndExtUserPrmData\n"),
       GsdError::kOutOfRange,
       "m.gsd:6: allowed values 0..256 do not fit Unsigned8 (0..255): `Unsigned8 0 0-256`"},
      {"default outside range",
       minimal("ExtUserPrmData = 1 \"A\"\nUnsigned16 5 10-1000\nEndExtUserPrmData\n"),
       GsdError::kOutOfRange, "m.gsd:6: default 5 is not within 10..1000: `Unsigned16 5 10-1000`"},
      {"default not in list",
       minimal("ExtUserPrmData = 1 \"A\"\nUnsigned8 2 0,1,4\nEndExtUserPrmData\n"),
       GsdError::kOutOfRange, "m.gsd:6: default 2 is not within 0, 1, 4: `Unsigned8 2 0,1,4`"},
      {"empty range", minimal("ExtUserPrmData = 1 \"A\"\nUnsigned8 2 5-1\nEndExtUserPrmData\n"),
       GsdError::kOutOfRange, "m.gsd:6: range 5..1 is empty: `Unsigned8 2 5-1`"},
      {"type line without range",
       minimal("ExtUserPrmData = 1 \"A\"\nUnsigned8 2\nEndExtUserPrmData\n"), GsdError::kBadValue,
       "m.gsd:6: type line expects: Unsigned8 <default> <min-max | a,b,…>: `Unsigned8 2`"},
      {"two type lines",
       minimal("ExtUserPrmData = 1 \"A\"\nBit(0) 0 0-1\nBit(1) 0 0-1\nEndExtUserPrmData\n"),
       GsdError::kDuplicate, "m.gsd:7: second type line in ExtUserPrmData 1: `Bit(1) 0 0-1`"},
      {"Prm_Text_Ref to nothing",
       minimal("ExtUserPrmData = 1 \"A\"\nBit(0) 0 0-1\nPrm_Text_Ref = 7\nEndExtUserPrmData\n"),
       GsdError::kUnknownReference, "m.gsd:5: Prm_Text_Ref = 7 names no PrmText: `A`"},
      {"module without name", minimal("Module = 0x10\nEndModule\n"), GsdError::kBadValue,
       "m.gsd:5: Module expects = \"name\" cfg,cfg,…: `Module = 0x10`"},
      {"module cfg truncated", minimal("Module = \"F\" 0xC4,0x84,0x84,0x05\nEndModule\n"),
       GsdError::kBadCfg,
       "m.gsd:5: module \"F\": Cfg identifier at byte 0: manufacturer-specific bytes missing: "
       "`Module = \"F\" 0xC4,0x84,0x84,0x05`"},
      {"module prm without length",
       minimal("Module = \"a\" 0x10\nExt_User_Prm_Data_Const(0) = 1\nEndModule\n"),
       GsdError::kMissingKeyword,
       "m.gsd:5: module \"a\" has parameter bytes but no Ext_Module_Prm_Data_Len: `Module = \"a\" "
       "0x10`"},
      {"module const beyond length",
       minimal("Module = \"a\" 0x10\nExt_Module_Prm_Data_Len = 1\n"
               "Ext_User_Prm_Data_Const(0) = 1,2\nEndModule\n"),
       GsdError::kOutOfRange,
       "m.gsd:7: module \"a\": constant bytes end at byte 2, beyond the length 1: "
       "`Ext_User_Prm_Data_Const(0) = 1,2`"},
      {"module ref beyond length",
       minimal("ExtUserPrmData = 1 \"W\"\nUnsigned16 0 0-9\nEndExtUserPrmData\n"
               "Module = \"a\" 0x10\nExt_Module_Prm_Data_Len = 2\n"
               "Ext_User_Prm_Data_Ref(1) = 1\nEndModule\n"),
       GsdError::kOutOfRange,
       "m.gsd:10: module \"a\": parameter ends at byte 3, beyond the length 2: "
       "`Ext_User_Prm_Data_Ref(1) = 1`"},
      {"F-prm without length",
       minimal("Module = \"a\" 0x10\nF_Ext_User_Prm_Data_Const(0) = 1\nEndModule\n"),
       GsdError::kMissingKeyword,
       "m.gsd:5: module \"a\" F-parameters has parameter bytes but no F_Ext_Module_Prm_Data_Len: "
       "`Module = \"a\" 0x10`"},
      {"two reference lines", minimal("Module = \"a\" 0x10\n1\n2\nEndModule\n"),
       GsdError::kBadValue, "m.gsd:7: a module takes one reference number line: `2`"},
      {"F_ParamDescCRC too big",
       minimal("Module = \"a\" 0x10\nF_ParamDescCRC = 70000\nEndModule\n"), GsdError::kOutOfRange,
       "m.gsd:6: F_ParamDescCRC = 70000 is out of range 0..65535: `F_ParamDescCRC = 70000`"},
  };
  return kCases;
}

// Lines the master can do without: taken at the limit or skipped, with a warning naming
// file:line (docs/gsd.md "The rule"); the file is read.
struct WarningCase {
  const char* title;
  std::string text;
  std::string warning;
};

const std::vector<WarningCase>& warning_cases() {
  static const std::vector<WarningCase> kCases = {
      {"ident twice", minimal("Ident_Number = 0x1234\n"),
       "m.gsd:5: Ident_Number already given at line 2; this later value taken: "
       "`Ident_Number = 0x1234`"},
      {"MaxTsdr missing", "#Profibus_DP\nIdent_Number = 1\n3M_supp = 1\n",
       "m.gsd:3: MaxTsdr_3M is missing; the master keeps its own slot time at this rate: "
       "`3M_supp = 1`"},
      {"flag not 0/1", minimal("Fail_Safe = 2\n"),
       "m.gsd:5: Fail_Safe = 2 is out of range 0..1; 1 taken: `Fail_Safe = 2`"},
      {"C1_Max_Data_Len > 240", minimal("C1_Max_Data_Len = 241\n"),
       "m.gsd:5: C1_Max_Data_Len = 241 is out of range 0..240; 240 taken: "
       "`C1_Max_Data_Len = 241`"},
      {"Max_Input_Len > 244", minimal("Max_Input_Len = 249\n"),
       "m.gsd:5: Max_Input_Len = 249 is out of range 0..244; 244 taken: `Max_Input_Len = 249`"},
      {"vendor not a string", minimal("Vendor_Name = 5\n"),
       "m.gsd:5: Vendor_Name expects a \"string\"; line ignored: `Vendor_Name = 5`"},
      {"number not a number", minimal("Max_Module = \"x\"\n"),
       "m.gsd:5: Max_Module expects one number; line ignored: `Max_Module = \"x\"`"},
      {"PrmText with a stray line",
       minimal("PrmText = 1\nText(0) = \"a\"\nValue = 1\nEndPrmText\n"),
       "m.gsd:7: PrmText holds only Text(value) = \"…\" lines; line ignored: `Value = 1`"},
      {"PrmText value twice",
       minimal("PrmText = 1\nText(0) = \"a\"\nText(0) = \"b\"\nEndPrmText\n"),
       "m.gsd:7: Text(0) given twice; line ignored: `Text(0) = \"b\"`"},
      {"module twice", minimal("Module = \"a\" 0x10\nEndModule\nModule = \"A\" 0x20\nEndModule\n"),
       "m.gsd:7: module \"A\" already defined at line 5; a --module of this name takes the "
       "first: `Module = \"A\" 0x20`"},
      {"sub-family without family", minimal("Slave_Family = @AS-I\n"),
       "m.gsd:5: Slave_Family expects a family number, optionally followed by @sub-families; "
       "line ignored: `Slave_Family = @AS-I`"},
      {"family out of range", minimal("Slave_Family = 256@X\n"),
       "m.gsd:5: Slave_Family = 256 is out of range 0..255; line ignored: "
       "`Slave_Family = 256@X`"},
  };
  return kCases;
}

TEST(GsdInterpWarnings, EachForgivenClassHasItsWarning) {
  for (const auto& c : warning_cases()) {
    auto result = parse(c.text, "m.gsd");
    ASSERT_TRUE(result) << c.title << ": " << result.error().what();
    ASSERT_EQ(result.value().warnings.size(), 1U) << c.title;
    EXPECT_EQ(result.value().warnings[0].what(), c.warning) << c.title;
  }
}

TEST(GsdInterpWarnings, TheLimitIsTaken) {
  auto d = parse(minimal("Max_Input_Len = 249\nMax_Data_Len = 498\nFail_Safe = 2\n"), "m.gsd");
  ASSERT_TRUE(d) << d.error().what();
  EXPECT_EQ(d.value().max_input_len, 244);
  EXPECT_EQ(d.value().max_data_len, 488);
  EXPECT_TRUE(d.value().fail_safe);
}

TEST(GsdInterpErrors, EachMalformedClassHasItsMessage) {
  for (const auto& c : cases()) {
    auto result = parse(c.text, "m.gsd");
    ASSERT_FALSE(result) << c.title;
    EXPECT_EQ(result.error().code, c.code) << c.title;
    EXPECT_EQ(result.error().what(), c.what) << c.title;
  }
}

}  // namespace
}  // namespace rs4sim::gsd
