// Real-file constructs ([PROFIBUS GSD spec]): the sub-family form of Slave_Family, ISO 8859-1
// text, words that are not GSD keywords (skipped with a warning naming file:line, as
// engineering tools do), X_Unit_Diag_Area and UnitDiagType blocks, Bitmap keywords, continued
// lines. The two corpus files are the project's own, written in the style of vendor files:
// gateway_asi.gse (a modular DP-V1 DP/AS-i gateway, CRLF, GSD revision 5) and
// depart_moteur_fr.gsf (a French compact motor starter in ISO 8859-1 bytes, revision 4).
#include "gsd/config.h"
#include "gsd/interp.h"
#include "test_util.h"

#include <gtest/gtest.h>

namespace rs4sim::gsd {
namespace {

Device parse_ok(const std::string& name) {
  auto d = parse(gsd::testing::corpus(name), name);
  EXPECT_TRUE(d) << (d ? "" : d.error().what());
  return d ? d.value() : Device{};
}

TEST(GsdVendorStyle, SubFamilyFormOfSlaveFamily) {
  const Device d = parse_ok("gateway_asi.gse");
  ASSERT_TRUE(d.slave_family);
  EXPECT_EQ(*d.slave_family, 9);  // 9 = gateways
  EXPECT_EQ(d.sub_families, std::vector<std::string>{"AS-I"});
  // Several sub-families and the plain form.
  auto two = parse(gsd::testing::minimal("Slave_Family = 3@TdF@Block-IO/24V\n"), "f.gsd");
  ASSERT_TRUE(two) << two.error().what();
  EXPECT_EQ(*two.value().slave_family, 3);
  EXPECT_EQ(two.value().sub_families, (std::vector<std::string>{"TdF", "Block-IO/24V"}));
  auto plain = parse(gsd::testing::minimal("Slave_Family = 1\n"), "f.gsd");
  ASSERT_TRUE(plain) << plain.error().what();
  EXPECT_EQ(*plain.value().slave_family, 1);
  EXPECT_TRUE(plain.value().sub_families.empty());
}

TEST(GsdVendorStyle, MisspeltKeywordIsSkippedWithAWarningNamingFileAndLine) {
  const Device d = parse_ok("gateway_asi.gse");
  ASSERT_EQ(d.warnings.size(), 1U);
  EXPECT_EQ(d.warnings[0].line, 85);
  EXPECT_EQ(d.warnings[0].what(),
            "gateway_asi.gse:85: 'Unit_Diag_!Bit' is not a GSD keyword, line skipped "
            "(unexpected character '!'): `Unit_Diag_!Bit(3)     = \"misspelt in the vendor's "
            "file\"`");
}

TEST(GsdVendorStyle, WellFormedUnknownKeywordIsSkippedWithAWarningToo) {
  auto d =
      parse(gsd::testing::minimal("Vendor_Specific_Thing = 5\nMax_Diag_Data_Len = 20\n"), "v.gsd");
  ASSERT_TRUE(d) << d.error().what();
  ASSERT_EQ(d.value().warnings.size(), 1U);
  EXPECT_EQ(d.value().warnings[0].what(),
            "v.gsd:5: 'Vendor_Specific_Thing' is not a GSD keyword, line skipped: "
            "`Vendor_Specific_Thing = 5`");
  EXPECT_EQ(d.value().max_diag_data_len, 20);
  // A keyword of the specification the master does not need is skipped silently.
  auto quiet =
      parse(gsd::testing::minimal("Bitmap_Device = \"X\"\nTransmission_Delay_12M = 3\n"), "q.gsd");
  ASSERT_TRUE(quiet) << quiet.error().what();
  EXPECT_TRUE(quiet.value().warnings.empty());
}

TEST(GsdVendorStyle, AKnownKeywordMustStillBeWellFormed) {
  // The same stray character after a keyword of the specification is an error.
  auto d = parse(gsd::testing::minimal("Unit_Diag_Bit(3!) = \"x\"\n"), "e.gsd");
  ASSERT_FALSE(d);
  EXPECT_EQ(d.error().what(), "e.gsd:5: unexpected character '!': `Unit_Diag_Bit(3!) = \"x\"`");
  // A number out of range of a keyword the master can do without is taken at the limit, with
  // a warning (docs/gsd.md "The rule"); Ident_Number's is an error.
  auto r = parse(gsd::testing::minimal("Max_Diag_Data_Len = 245\n"), "e.gsd");
  ASSERT_TRUE(r) << r.error().what();
  EXPECT_EQ(r.value().max_diag_data_len, 244);
  ASSERT_EQ(r.value().warnings.size(), 1U);
  EXPECT_EQ(r.value().warnings[0].line, 5);
  auto ident =
      parse("#Profibus_DP\nIdent_Number = 0x10000\n12M_supp = 1\nMaxTsdr_12M = 1\n", "e.gsd");
  ASSERT_FALSE(ident);
  EXPECT_EQ(ident.error().code, GsdError::kOutOfRange);
}

TEST(GsdVendorStyle, ModularGatewayCapabilities) {
  const Device d = parse_ok("gateway_asi.gse");
  EXPECT_EQ(d.ident_number, 0x0B4E);
  EXPECT_EQ(d.gsd_revision, 5);
  EXPECT_EQ(d.model_name, "DP/AS-i Gateway 2x");
  EXPECT_TRUE(d.modular_station);
  EXPECT_EQ(d.max_module, 4);
  EXPECT_EQ(d.max_diag_data_len, 32);
  EXPECT_TRUE(d.dpv1.slave);
  EXPECT_TRUE(d.dpv1.c1_read_write);
  EXPECT_EQ(d.dpv1.c1_max_data_len, 64);
  const BaudRate* b15 = d.find_baud(1'500'000);
  ASSERT_NE(b15, nullptr);
  EXPECT_TRUE(b15->supported);
  EXPECT_EQ(b15->max_tsdr, 150);
  EXPECT_FALSE(d.find_baud(3'000'000)->supported);
  EXPECT_FALSE(d.find_baud(12'000'000)->supported);
  ASSERT_EQ(d.modules.size(), 3U);
  // 0x33: inputs and outputs (bits 5..4 = 11), 3 + 1 bytes ([IEC 61158-6-3 Chk_Cfg/Get_Cfg])
  EXPECT_EQ(d.modules[0].input_len, 4U);
  EXPECT_EQ(d.modules[0].output_len, 4U);
  // 0x51: words (bit 6), inputs (01), 1 + 1 words = 4 bytes
  EXPECT_EQ(d.modules[1].input_len, 4U);
  EXPECT_EQ(d.modules[1].output_len, 0U);
  EXPECT_EQ(d.modules[2].reference, 3U);
}

TEST(GsdVendorStyle, ModularGatewayUserPrmDataFromContinuedConstAndRefs) {
  const Device d = parse_ok("gateway_asi.gse");
  auto c = configure(d, {{"Digital 4 byte in/out", "Analog 2 words in"}, {}});
  ASSERT_TRUE(c) << c.error().what();
  // global: 80 00 00 (DPV1_Status_1..3, the continued Const line) | 00 (Bit(0) default 0)
  // | 02 (input filter default 2); module "Analog 2 words in": BitArea(4-7) default 7 → 0x70
  EXPECT_EQ(c.value().user_prm_data,
            (std::vector<std::uint8_t>{0x80, 0x00, 0x00, 0x00, 0x02, 0x70}));
  EXPECT_EQ(c.value().cfg, (std::vector<std::uint8_t>{0x33, 0x51}));
  EXPECT_EQ(c.value().input_len, 8U);
  EXPECT_EQ(c.value().output_len, 4U);
  // The list form: 3 is not one of 1, 2, 5, 10.
  auto bad = configure(d, {{"Status 1 byte"}, {{"Input filter (ms)", 3}}});
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().code, GsdError::kOutOfRange);
}

TEST(GsdVendorStyle, Latin1TextIsReadAndConvertedToUtf8) {
  const std::string raw = gsd::testing::corpus("depart_moteur_fr.gsf");
  ASSERT_NE(raw.find("D\xE9part-moteur"), std::string::npos);  // the file holds Latin-1 bytes
  const Device d = parse_ok("depart_moteur_fr.gsf");
  EXPECT_TRUE(d.latin1);
  EXPECT_TRUE(d.warnings.empty());
  EXPECT_EQ(d.model_name, "D\xC3\xA9part-moteur DM 400");  // é = U+00E9 = C3 A9
  EXPECT_EQ(d.revision, "R\xC3\xA9vision 1");
  EXPECT_EQ(d.sub_families, std::vector<std::string>{"D\xC3\xA9part-moteur"});
  ASSERT_EQ(d.modules.size(), 1U);
  EXPECT_EQ(d.modules[0].name, "D\xC3\xA9part-moteur 2 octets E/S");
  EXPECT_EQ(d.params.at(1).name,
            "R\xC3\xA9"
            "action \xC3\xA0 l'arr\xC3\xAAt du ma\xC3\xAEtre");
  EXPECT_EQ(d.prm_texts.at(1).texts.at(1), "derni\xC3\xA8re valeur");
  EXPECT_EQ(d.ident_number, 0x09C1);
  EXPECT_EQ(d.max_diag_data_len, 16);
  EXPECT_EQ(d.find_baud(1'500'000)->max_tsdr, 25);
}

TEST(GsdVendorStyle, FrenchCompactStationConfiguresWithItsImplicitModule) {
  const Device d = parse_ok("depart_moteur_fr.gsf");
  auto c = configure(d, {});
  ASSERT_TRUE(c) << c.error().what();
  // Const 00 00 00 14 | Bit(0) default 0 at byte 0 | 20 = 0x14 at 1 | 10 = 0x0A at 2
  EXPECT_EQ(c.value().user_prm_data, (std::vector<std::uint8_t>{0x00, 0x14, 0x0A, 0x14}));
  EXPECT_EQ(c.value().cfg, std::vector<std::uint8_t>{0x31});
  EXPECT_EQ(c.value().input_len, 2U);
  EXPECT_EQ(c.value().output_len, 2U);
  auto high = configure(d, {{}, {{"courant nominal (0,1 a)", 130}}});
  ASSERT_FALSE(high);
  EXPECT_EQ(high.error().what(), "Courant nominal (0,1 A) = 130 is out of range 5..120");
}

TEST(GsdSlaveCheck, UserPrmDataIsCheckedAgainstTheGsdRangesAndLists) {
  const Device d = parse_ok("gateway_asi.gse");
  auto c = configure(d, {{"Digital 4 byte in/out", "Analog 2 words in"}, {}});
  ASSERT_TRUE(c) << c.error().what();
  using Bytes = std::vector<std::uint8_t>;
  EXPECT_TRUE(check_user_prm(d, c.value(), Bytes{0x80, 0x00, 0x00, 0x00, 0x02, 0x70}));
  // Other values inside the GSD's ranges: mode bit 1, filter 10, profile 15.
  EXPECT_TRUE(check_user_prm(d, c.value(), Bytes{0x80, 0x00, 0x00, 0x01, 0x0A, 0xF0}));
  // Input filter 3 ms is not in the list 1, 2, 5, 10.
  auto list = check_user_prm(d, c.value(), Bytes{0x80, 0x00, 0x00, 0x00, 0x03, 0x70});
  ASSERT_FALSE(list);
  EXPECT_EQ(list.error().code, GsdError::kOutOfRange);
  EXPECT_EQ(list.error().what(), "byte 4: Input filter (ms) = 3 is not allowed (1, 2, 5, 10)");
  // One byte short.
  auto shorter = check_user_prm(d, c.value(), Bytes{0x80, 0x00, 0x00, 0x00, 0x02});
  ASSERT_FALSE(shorter);
  EXPECT_EQ(shorter.error().what(), "User_Prm_Data is 5 bytes, the GSD configuration has 6");

  const Device fr = parse_ok("depart_moteur_fr.gsf");
  auto cf = configure(fr, {});
  ASSERT_TRUE(cf) << cf.error().what();
  // Rated current 4 (0.4 A) is below the range 5..120; trip class 15 is not in 5, 10, 20, 30.
  auto low = check_user_prm(fr, cf.value(), Bytes{0x00, 0x04, 0x0A, 0x14});
  ASSERT_FALSE(low);
  EXPECT_EQ(low.error().what(), "byte 1: Courant nominal (0,1 A) = 4 is not allowed (5..120)");
  auto trip = check_user_prm(fr, cf.value(), Bytes{0x01, 0x78, 0x0F, 0x14});
  ASSERT_FALSE(trip);
  EXPECT_EQ(trip.error().what(),
            "byte 2: Classe de d\xC3\xA9"
            "clenchement = 15 is not allowed (5, 10, 20, 30)");
  EXPECT_TRUE(check_user_prm(fr, cf.value(), Bytes{0x01, 0x78, 0x1E, 0x14}));
}

TEST(GsdSlaveCheck, SignedParametersAreReadAsTwosComplement) {
  auto d = parse(gsd::testing::minimal("User_Prm_Data_Len = 2\nExt_User_Prm_Data_Ref(0) = 1\n"
                                       "ExtUserPrmData = 1 \"Offset\"\nSigned16 0 -100-100\n"
                                       "EndExtUserPrmData\nModule = \"m\" 0x10\nEndModule\n"),
                 "s.gsd");
  ASSERT_TRUE(d) << d.error().what();
  auto c = configure(d.value(), {});
  ASSERT_TRUE(c) << c.error().what();
  using Bytes = std::vector<std::uint8_t>;
  EXPECT_TRUE(check_user_prm(d.value(), c.value(), Bytes{0xFF, 0x9C}));  // -100
  auto below = check_user_prm(d.value(), c.value(), Bytes{0xFF, 0x9B});  // -101
  ASSERT_FALSE(below);
  EXPECT_EQ(below.error().what(), "byte 0: Offset = -101 is not allowed (-100..100)");
  EXPECT_FALSE(check_user_prm(d.value(), c.value(), Bytes{0x00, 0x65}));  // 101
}

TEST(GsdVendorStyle, Utf8FilesStayAsTheyAre) {
  bool converted = true;
  EXPECT_EQ(syntax::to_utf8("Info_Text = \"\xC3\xA9\"", &converted), "Info_Text = \"\xC3\xA9\"");
  EXPECT_FALSE(converted);
  // A lone continuation byte, a truncated sequence, an overlong form: not UTF-8 → Latin-1.
  EXPECT_EQ(syntax::to_utf8("\xA9", &converted), "\xC2\xA9");
  EXPECT_TRUE(converted);
  EXPECT_EQ(syntax::to_utf8("a\xC3", &converted), "a\xC3\x83");
  EXPECT_EQ(syntax::to_utf8("\xC0\xAF", &converted), "\xC3\x80\xC2\xAF");
  EXPECT_TRUE(converted);
}

// SINAMICS-style: `UnitDiagType = 129` holding `X_Unit_Diag_Area=24-31` … `X_Unit_Diag_Area_End`.
TEST(GsdVendorStyle, AnXUnitDiagAreaMayStandInsideAUnitDiagType) {
  auto d = parse(gsd::testing::minimal("UnitDiagType = 129\nX_Unit_Diag_Area=24-31\n"
                                       "X_Value(0) = \"none\"\nX_Unit_Diag_Area_End\n"
                                       "EndUnitDiagType\nMax_Diag_Data_Len = 20\n"),
                 "g120.gsd");
  ASSERT_TRUE(d) << d.error().what();
  EXPECT_EQ(d.value().max_diag_data_len, 20);
  EXPECT_TRUE(d.value().warnings.empty());
  // Any other block inside stays an error, and so does an inner block left open.
  auto module = parse(gsd::testing::minimal("UnitDiagType = 1\nModule = \"a\" 0x10\n"), "m.gsd");
  ASSERT_FALSE(module);
  EXPECT_EQ(module.error().what(),
            "m.gsd:6: Module inside UnitDiagType started at line 5: `Module = \"a\" 0x10`");
  auto open = parse(gsd::testing::minimal("UnitDiagType = 1\nX_Unit_Diag_Area = 1-2\n"
                                          "EndUnitDiagType\n"),
                    "o.gsd");
  ASSERT_FALSE(open);
  EXPECT_EQ(open.error().what(),
            "o.gsd:7: X_Unit_Diag_Area started at line 6 is not closed (X_Unit_Diag_Area_End "
            "missing): `EndUnitDiagType`");
}

TEST(GsdVendorStyle, SubFamilyNamesWithBlanks) {
  auto d = parse(gsd::testing::minimal("Slave_Family = 2@Motor starter@Direct soft starter  \n"),
                 "s.gsd");
  ASSERT_TRUE(d) << d.error().what();
  EXPECT_EQ(d.value().slave_family, 2);
  EXPECT_EQ(d.value().sub_families,
            (std::vector<std::string>{"Motor starter", "Direct soft starter"}));
}

}  // namespace
}  // namespace rs4sim::gsd
