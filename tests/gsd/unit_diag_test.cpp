// The GSD's diagnosis texts ([PROFIBUS GSD spec Unit_Diag_Bit, Unit_Diag_Area]): what
// gateway_asi.gse (the project's vendor-style test file) declares, and the texts for
// Ext_Diag_Data bytes written by hand ([IEC 61158-6-3 Slave_Diag] device-related block: header
// bits 7..6 = 00, bits 5..0 = length with the header). Bit n = bit n % 8 of data byte n / 8
// after the header (docs/decisions.md gsd-unit-diag-bits).
#include "gsd/unit_diag.h"

#include "gsd/interp.h"
#include "test_util.h"

#include <gtest/gtest.h>

namespace rs4sim::gsd {
namespace {

using Bytes = std::vector<std::uint8_t>;
using Texts = std::vector<std::string>;

Device gateway() {
  auto d = parse(testing::corpus("gateway_asi.gse"), "gateway_asi.gse");
  EXPECT_TRUE(d) << (d ? "" : d.error().what());
  return d ? d.value() : Device{};
}

TEST(GsdUnitDiag, TheGatewaysTextsAreRead) {
  const UnitDiag u = gateway().unit_diag;
  EXPECT_EQ(u.bits, (std::map<std::uint16_t, std::string>{{16, "AS-i voltage too low"},
                                                          {17, "AS-i configuration error"}}));
  EXPECT_EQ(u.not_bits,
            (std::map<std::uint16_t, std::string>{{18, "gateway not in protected mode"}}));
  ASSERT_EQ(u.areas.size(), 1U);  // X_Unit_Diag_Area (no UnitDiagType around it) is not one
  EXPECT_EQ(u.areas[0].first, 24);
  EXPECT_EQ(u.areas[0].last, 27);
  EXPECT_EQ(u.areas[0].values, (std::map<std::uint32_t, std::string>{
                                   {0, "no fault"}, {1, "earth fault"}, {2, "double address"}}));
}

TEST(GsdUnitDiag, TextsOfHandWrittenDiagnosisBytes) {
  const UnitDiag u = gateway().unit_diag;
  // 05 = device-related, 5 bytes with the header; data byte 2 = bits 16..23, byte 3 = 24..31.
  // Bit 16 set, bit 18 set (protected mode), bits 24..27 = 2.
  EXPECT_EQ(unit_diag_texts(u, Bytes{0x05, 0x00, 0x00, 0x05, 0x02}),
            (Texts{"AS-i voltage too low", "double address"}));
  // Bit 17 set, bit 18 clear, bits 24..27 = 7 (a value the GSD names not); bits 28..31 are
  // outside the area.
  EXPECT_EQ(unit_diag_texts(u, Bytes{0x05, 0x00, 0x00, 0x02, 0xF7}),
            (Texts{"AS-i configuration error", "gateway not in protected mode",
                   "Unit_Diag_Area 24-27: value 7"}));
  // A block of 2 data bytes holds none of the bits: no text, not even the Not_Bit's.
  EXPECT_EQ(unit_diag_texts(u, Bytes{0x03, 0xFF, 0xFF}), Texts{});
  // Bits 16..23 only (4 bytes with the header): the area is beyond the block.
  EXPECT_EQ(unit_diag_texts(u, Bytes{0x04, 0x00, 0x00, 0x00}),
            Texts{"gateway not in protected mode"});
  // The block's length, not the bytes after it: a second block (identifier-related, 0x42)
  // follows; its bits are not read.
  EXPECT_EQ(unit_diag_texts(u, Bytes{0x04, 0x00, 0x00, 0x04, 0x42, 0xFF}), Texts{});
}

TEST(GsdUnitDiag, NoDeviceRelatedBlockNoTexts) {
  const UnitDiag u = gateway().unit_diag;
  EXPECT_EQ(unit_diag_texts(u, Bytes{}), Texts{});
  EXPECT_EQ(unit_diag_texts(u, Bytes{0x45, 0x00, 0x00, 0x01, 0x00}), Texts{});  // identifier
  EXPECT_EQ(unit_diag_texts(u, Bytes{0x85, 0x00, 0x00, 0x01, 0x00}), Texts{});  // channel
  EXPECT_EQ(unit_diag_texts(u, Bytes{0x09, 0x00, 0x00, 0x01}), Texts{});  // longer than the bytes
  EXPECT_EQ(unit_diag_texts(u, Bytes{0x01}), Texts{});                    // a header alone
}

// UnitDiagType = 129 … X_Unit_Diag_Bit(8) = "peripheral fault" … EndUnitDiagType of
// gateway_asi.gse: the text belongs to blocks whose first byte after the header is 129 (0x81, a
// DPV1 status message), read with the file's other texts in bit order; its X_Unit_Diag_Area
// 32-39 outside any UnitDiagType is not read (docs/decisions.md gsd-unit-diag-types).
TEST(GsdUnitDiag, TheTextsOfAUnitDiagTypeApplyToItsBlocksOnly) {
  const UnitDiag u = gateway().unit_diag;
  ASSERT_EQ(u.types.size(), 1U);
  EXPECT_EQ(u.types.at(129).bits, (std::map<std::uint16_t, std::string>{{8, "peripheral fault"}}));
  EXPECT_EQ(u.areas.size(), 1U);
  // 06 81 01 00 00 05: type 0x81, bit 8 set; bit 18 clear; 24-27 = 0; 32-39 = 5
  EXPECT_EQ(unit_diag_texts(u, Bytes{0x06, 0x81, 0x01, 0x00, 0x00, 0x05}),
            (Texts{"peripheral fault", "gateway not in protected mode", "no fault"}));
  // the same bits in a block of type 0x01 (a diagnostic alarm): not the type's text
  EXPECT_EQ(unit_diag_texts(u, Bytes{0x06, 0x01, 0x01, 0x00, 0x00, 0x05}),
            (Texts{"gateway not in protected mode", "no fault"}));
}

// A UnitDiagType holding X_Unit_Diag_Area blocks with X_Value texts, the layout a vendor's file
// gives a diagnostic alarm (type 1: header, type, slot, specifier, then the alarm's data from bit
// 24); and Channel_Diag(n), the name of a manufacturer-specific channel error type.
TEST(GsdUnitDiag, XValuesOfAUnitDiagTypeAndChannelDiagTexts) {
  auto d = parse(testing::minimal("UnitDiagType = 1\nX_Unit_Diag_Area = 24-24\n"
                                  "X_Value(1) = \"Slot 1: high-limit\"\nX_Unit_Diag_Area_End\n"
                                  "X_Unit_Diag_Area = 25-25\nX_Value(1) = \"Slot 1: low-limit\"\n"
                                  "X_Unit_Diag_Area_End\nEndUnitDiagType\n"
                                  "Channel_Diag(16) = \"wire break at the sensor\"\n"),
                 "m.gsd");
  ASSERT_TRUE(d) << d.error().what();
  const UnitDiag& u = d.value().unit_diag;
  EXPECT_TRUE(d.value().warnings.empty());
  // 05 01 01 01 02: diagnostic alarm, slot 1, appears, data 02 = bit 25; bit 24 is 0, a value
  // without a text of its own: the area's default text (docs/decisions.md gsd-unit-diag-bits)
  EXPECT_EQ(unit_diag_texts(u, Bytes{0x05, 0x01, 0x01, 0x01, 0x02}),
            (Texts{"Unit_Diag_Area 24-24: value 0", "Slot 1: low-limit"}));
  EXPECT_EQ(unit_diag_texts(u, Bytes{0x05, 0x01, 0x01, 0x01, 0x01}),
            (Texts{"Slot 1: high-limit", "Unit_Diag_Area 25-25: value 0"}));
  // a status message (0x81) with the same bits: not type 1's texts
  EXPECT_EQ(unit_diag_texts(u, Bytes{0x05, 0x81, 0x01, 0x01, 0x03}), Texts{});
  EXPECT_EQ(channel_error_text(u, 16), "wire break at the sensor");
  EXPECT_EQ(channel_error_text(u, 17), "");
  auto low = parse(testing::minimal("Channel_Diag(9) = \"x\"\n"), "m.gsd");
  ASSERT_TRUE(low);
  ASSERT_EQ(low.value().warnings.size(), 1U);
  EXPECT_EQ(low.value().warnings[0].what(),
            "m.gsd:5: Channel_Diag(9) is out of range 16..31; line ignored: "
            "`Channel_Diag(9) = \"x\"`");
}

// Diagnosis texts never change what the master sends: a line rs4sim cannot read is skipped
// with a warning naming it (docs/gsd.md "The rule").
TEST(GsdUnitDiag, UnreadableLinesAreSkippedWithAWarningNamingTheLine) {
  const auto what = [](const std::string& rest) {
    auto d = parse(testing::minimal(rest), "m.gsd");
    if (!d) return "refused: " + d.error().what();
    if (d.value().warnings.size() != 1)
      return std::string("warnings: ") + std::to_string(d.value().warnings.size());
    const std::string w = d.value().warnings[0].what();
    const auto cut = w.find("; line ignored");
    return cut == std::string::npos ? w : w.substr(0, cut) + w.substr(cut + 14);
  };
  EXPECT_EQ(what("Unit_Diag_Bit(3) = \"a\"\nUnit_Diag_Bit(3) = \"b\"\n"),
            "m.gsd:6: Unit_Diag_Bit(3) given twice: `Unit_Diag_Bit(3) = \"b\"`");
  EXPECT_EQ(what("Unit_Diag_Bit(3) = 5\n"),
            "m.gsd:5: Unit_Diag_Bit expects a \"string\": `Unit_Diag_Bit(3) = 5`");
  EXPECT_EQ(what("Unit_Diag_Bit(1896) = \"a\"\n"),
            "m.gsd:5: Unit_Diag_Bit(1896) is out of range 0..1895: `Unit_Diag_Bit(1896) = \"a\"`");
  EXPECT_EQ(what("Unit_Diag_Area = 27-24\nUnit_Diag_Area_End\n"),
            "m.gsd:5: Unit_Diag_Area = 27-24: bits 0..1895, first <= last, 32 bits at most: "
            "`Unit_Diag_Area = 27-24`");
  EXPECT_EQ(what("Unit_Diag_Area = 8-9\nValue(4) = \"x\"\nUnit_Diag_Area_End\n"),
            "m.gsd:6: Value(4) is out of range 0..3: `Value(4) = \"x\"`");
  EXPECT_EQ(what("Unit_Diag_Area = 8-9\nValue(1) = \"x\"\nValue(1) = \"y\"\nUnit_Diag_Area_End\n"),
            "m.gsd:7: Value(1) given twice: `Value(1) = \"y\"`");
}

// An F-device's diagnosis 64..71 [IEC 61784-3-3 F-Parameters] in its status block `05 81 slot 00
// nn` ([IEC 61158-6-3 DPV1 status]: Status_Type 0x81 = UnitDiagType 129, nn = bits 24-31). The
// project's f_module_v1.gsd names 64..70 in the vendors' form (X_Value(64) = "F add. does not
// match F_Dest_Add", a drive maker's words) and not 71; f_module_v2.gsd names none: there the
// standard's meaning stands.
TEST(GsdUnitDiag, AnFDevicesDiagnosisByTheGsdsXValueElseTheStandards) {
  auto v1 = parse(testing::corpus("f_module_v1.gsd"), "f_module_v1.gsd");
  auto v2 = parse(testing::corpus("f_module_v2.gsd"), "f_module_v2.gsd");
  ASSERT_TRUE(v1 && v2);
  const UnitDiag& own = v1.value().unit_diag;
  EXPECT_EQ(f_diagnosis_text(own, 64), "F add. does not match F_Dest_Add");
  EXPECT_EQ(f_diagnosis_text(own, 70), "F-parameter version wrong");
  EXPECT_EQ(f_diagnosis_text(own, 71), "CRC1 fault (F_Par_CRC)");  // the standard's
  EXPECT_EQ(f_diagnosis_text(v2.value().unit_diag, 64),
            "Mismatch of safety destination address (F_Dest_Add)");
  EXPECT_EQ(f_diagnosis_text(own, 72), "");  // not one of 64..71
  // The block of slot 1 with 64: the GSD's text once (not the standard's beside it).
  const Bytes dest{0x05, 0x81, 0x01, 0x00, 64};
  EXPECT_EQ(device_diag_texts(own, true, dest), Texts{"F add. does not match F_Dest_Add"});
  EXPECT_EQ(device_diag_texts(v2.value().unit_diag, true, dest),
            Texts{"Mismatch of safety destination address (F_Dest_Add)"});
  // 71 (0x47): the GSD's area has no value for it, then the standard's meaning.
  EXPECT_EQ(device_diag_texts(own, true, Bytes{0x05, 0x81, 0x01, 0x00, 0x47}),
            (Texts{"Unit_Diag_Area 24-31: value 71", "CRC1 fault (F_Par_CRC)"}));
  // Not an F-device, or not its status block (an alarm type 1, a longer block): the GSD alone.
  EXPECT_EQ(device_diag_texts(v2.value().unit_diag, false, dest), Texts{});
  EXPECT_EQ(device_diag_texts(v2.value().unit_diag, true, Bytes{0x05, 0x01, 0x01, 0x00, 64}),
            Texts{});
  EXPECT_EQ(device_diag_texts(v2.value().unit_diag, true, Bytes{0x06, 0x81, 1, 0, 64, 0}),
            Texts{});
}

}  // namespace
}  // namespace rs4sim::gsd
