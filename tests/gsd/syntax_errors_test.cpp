// The malformed-GSD suite, syntax stage: each error names file:line and the offending
// text, with one specific message per class of mistake.
#include "gsd/interp.h"
#include "gsd/syntax.h"

#include <gtest/gtest.h>

namespace rs4sim::gsd {
namespace {

struct Case {
  const char* title;
  const char* text;
  GsdError code;
  const char* what;  // the full Error::what()
};

const Case kCases[] = {
    {"empty file", "", GsdError::kMissingHeader,
     "bad.gsd:1: no keyword line: the file must start with #Profibus_DP"},
    {"only comments", "; nothing\n\n", GsdError::kMissingHeader,
     "bad.gsd:1: no keyword line: the file must start with #Profibus_DP"},
    {"header missing", "; x\nIdent_Number = 1\n", GsdError::kMissingHeader,
     "bad.gsd:2: the first keyword line must be #Profibus_DP: `Ident_Number = 1`"},
    {"wrong header", "#Profibus_PA\n", GsdError::kMissingHeader,
     "bad.gsd:1: the first keyword line must be #Profibus_DP: `#Profibus_PA`"},
    {"second header", "#Profibus_DP\n#Profibus_DP\n", GsdError::kBlockStructure,
     "bad.gsd:2: second #Profibus_DP header: `#Profibus_DP`"},
    {"unterminated string", "#Profibus_DP\nVendor_Name = \"abc\n", GsdError::kSyntax,
     "bad.gsd:2: unterminated string: `\"abc`"},
    {"stray character", "#Profibus_DP\nIdent_Number = 0x12!4\n", GsdError::kSyntax,
     "bad.gsd:2: unexpected character '!': `Ident_Number = 0x12!4`"},
    {"control byte", "#Profibus_DP\nVendor_Name = \x01\n", GsdError::kSyntax,
     "bad.gsd:2: unexpected byte 0x01: `Vendor_Name = \\x01`"},  // shown, not sent raw
    {"bad hex", "#Profibus_DP\nIdent_Number = 0x12G4\n", GsdError::kSyntax,
     "bad.gsd:2: malformed hex number: `0x12G4`"},
    {"bare 0x", "#Profibus_DP\nIdent_Number = 0x\n", GsdError::kSyntax,
     "bad.gsd:2: malformed hex number: `0x`"},
    {"number too large", "#Profibus_DP\nMax_Module = 4294967296\n", GsdError::kSyntax,
     "bad.gsd:2: number too large: `4294967296`"},
    {"nothing after =", "#Profibus_DP\nIdent_Number =\n", GsdError::kSyntax,
     "bad.gsd:2: value expected after '=' near 'end of line': `Ident_Number =`"},
    {"dangling comma", "#Profibus_DP\nUser_Prm_Data = 1,\n", GsdError::kSyntax,
     "bad.gsd:2: value expected near 'end of line': `User_Prm_Data = 1,`"},
    {"unclosed args", "#Profibus_DP\nBit(0 1 0-1\n", GsdError::kSyntax,
     "bad.gsd:2: ')' expected near '1': `Bit(0 1 0-1`"},
    {"line starts with =", "#Profibus_DP\n= 5\n", GsdError::kSyntax,
     "bad.gsd:2: keyword expected near '=': `= 5`"},
    {"range without high end", "#Profibus_DP\nUnsigned8 1 1-\n", GsdError::kSyntax,
     "bad.gsd:2: number expected near 'end of line': `Unsigned8 1 1-`"},
    {"continuation at end of file", "#Profibus_DP\nA = 1, \\", GsdError::kSyntax,
     "bad.gsd:2: '\\' continues past the end of the file: `A = 1, `"},
    {"unterminated module", "#Profibus_DP\nModule = \"DI 8\" 0x10\nUnit_Diag_!Bit(3) = \"x\"\n",
     GsdError::kBlockStructure,
     "bad.gsd:2: Module is not closed (EndModule missing): `Module = \"DI 8\" 0x10`"},
    {"unterminated X_Unit_Diag_Area",
     "#Profibus_DP\nX_Unit_Diag_Area = 16-17\nX_Value(0) = \"ok\"\n", GsdError::kBlockStructure,
     "bad.gsd:2: X_Unit_Diag_Area is not closed (X_Unit_Diag_Area_End missing): "
     "`X_Unit_Diag_Area = 16-17`"},
    {"End without block", "#Profibus_DP\nEndModule\n", GsdError::kBlockStructure,
     "bad.gsd:2: EndModule without Module: `EndModule`"},
    {"wrong End", "#Profibus_DP\nPrmText = 1\nText(0) = \"a\"\nEndModule\n",
     GsdError::kBlockStructure, "bad.gsd:4: EndModule without Module: `EndModule`"},
    {"nested block", "#Profibus_DP\nModule = \"a\" 0x10\nPrmText = 1\n", GsdError::kBlockStructure,
     "bad.gsd:3: PrmText inside Module started at line 2: `PrmText = 1`"},
    {"block not closed", "#Profibus_DP\nA = 1\nModule = \"a\" 0x10\n1\n", GsdError::kBlockStructure,
     "bad.gsd:3: Module is not closed (EndModule missing): `Module = \"a\" 0x10`"},
    {"End with value", "#Profibus_DP\nModule = \"a\" 0x10\nEndModule = 1\n",
     GsdError::kBlockStructure, "bad.gsd:3: EndModule takes no value: `EndModule = 1`"},
};

TEST(GsdSyntaxErrors, EachMalformedClassHasItsMessage) {
  for (const auto& c : kCases) {
    auto result = parse(c.text, "bad.gsd");
    ASSERT_FALSE(result) << c.title;
    EXPECT_EQ(result.error().code, c.code) << c.title;
    EXPECT_EQ(result.error().what(), c.what) << c.title;
    EXPECT_EQ(result.error().error_code().category().name(), std::string("rs4sim.gsd"));
  }
}

TEST(GsdSyntaxErrors, LineNumberIsThePhysicalLineOfTheStatement) {
  auto result = parse("; 1\n; 2\n#Profibus_DP\n\nA = 1, \\\n  2\nVendor_Name = \"x\n", "f.gsd");
  ASSERT_FALSE(result);
  EXPECT_EQ(result.error().line, 7);
  EXPECT_EQ(result.error().file, "f.gsd");
}

TEST(GsdSyntaxErrors, VeryLongLineIsRefused) {
  std::string text = "#Profibus_DP\nA = 1";
  for (int i = 0; i < 70000; ++i) text += ",1";
  auto result = parse(text, "long.gsd");
  ASSERT_FALSE(result);
  EXPECT_EQ(result.error().message, "line too long");
  EXPECT_EQ(result.error().line, 2);
}

}  // namespace
}  // namespace rs4sim::gsd
