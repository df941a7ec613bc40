// rpc::fill_diagnosis on Slave_Diag answers written out by hand, byte by byte:
//  - the standard part [IEC 61158-6-3 Slave_Diag]: 0A = Station_Not_Ready (bit 1) + Ext_Diag
//    (bit 3); 0C = the always-1 bit 2 + WD_On (bit 3); 00; master 01; ident 0x097A;
//  - the RS4's F-parameter diagnosis, the status PDU 05 81 00 00 42 of [RS4 manual §6.3]:
//    66 = wrong F_Dest_Add (table 6.3-1);
//  - the RS4's diagnosis alarm of [RS4 manual §5.3.2]: 0D 01 00, specifier 0x0D (seq 1, Add_Ack,
//    appears), user data 84, μC2 error 26 00 count 00 01, μC1 error 26 00 count 00 01:
//    0x2600 "wrong protective field pair number" (table 5.3-3);
//  - a DP-V0 slave's identifier block 43 05 00 (header 01 000011: 3 bytes with the header; bits
//    0 and 2 set: modules 0 and 2) and a channel block 82 41 21 (header 10 000010: module 2;
//    01 000001: input, channel 1; 001 00001: type bit, error 1 short circuit).
#include "gsd/interp.h"
#include "gsd/station/gsd_station.h"
#include "rpc/diagnosis_view.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <string>
#include <vector>

namespace rs4sim::rpc {
namespace {

v1::DiagnosisView decoded(const std::vector<std::uint8_t>& du, bool dpv1, const DiagnosisTexts& texts) {
  v1::DiagnosisView view;
  fill_diagnosis(du, dpv1, texts, view);
  return view;
}

std::vector<std::string> list(const google::protobuf::RepeatedPtrField<std::string>& r) {
  return {r.begin(), r.end()};
}

TEST(DiagnosisView, TheRs4sFDiagnosisByItsTable) {
  const auto v = decoded({0x0A, 0x0C, 0x00, 0x01, 0x09, 0x7A, 0x05, 0x81, 0x00, 0x00, 0x42}, true,
                         rs4_diagnosis_texts);
  EXPECT_EQ(list(v.station_status()), (std::vector<std::string>{"Station_Not_Ready", "Ext_Diag", "WD_On"}));
  EXPECT_EQ(v.master_address(), 1U);
  EXPECT_EQ(v.ident_number(), 0x097AU);
  ASSERT_EQ(v.blocks_size(), 1);
  EXPECT_EQ(v.blocks(0).kind(), "status");
  EXPECT_EQ(v.blocks(0).data(), std::string("\x42", 1));
  EXPECT_EQ(v.blocks(0).summary(), "status type 1 slot 0, 1 bytes");
  EXPECT_EQ(list(v.texts()), (std::vector<std::string>{"66 wrong F_Dest_Add"}));
  EXPECT_EQ(v.error(), "");
  EXPECT_EQ(v.raw().size(), 11U);
}

TEST(DiagnosisView, TheRs4sDiagnosisAlarmByTable533) {
  const auto v = decoded({0x08, 0x0C, 0x00, 0x01, 0x09, 0x7A, 0x0D, 0x01, 0x00, 0x0D, 0x84, 0x26,
                          0x00, 0x00, 0x01, 0x26, 0x00, 0x00, 0x01},
                         true, rs4_diagnosis_texts);
  ASSERT_EQ(v.blocks_size(), 1);
  EXPECT_EQ(v.blocks(0).kind(), "alarm");
  EXPECT_EQ(v.blocks(0).summary(), "alarm type 1 (diagnostic) slot 0 seq 1 appears, Add_Ack");
  EXPECT_EQ(list(v.texts()), (std::vector<std::string>{
                                 "coming: 0x2600 wrong protective field pair number, 1 since power-up"}));
}

TEST(DiagnosisView, IdentifierAndChannelBlocksOfADpV0Slave) {
  const auto v = decoded({0x08, 0x0C, 0x00, 0x02, 0x12, 0x34, 0x43, 0x05, 0x00, 0x82, 0x41, 0x21},
                         false, {});
  ASSERT_EQ(v.blocks_size(), 2);
  EXPECT_EQ(v.blocks(0).kind(), "identifier");
  EXPECT_EQ(v.blocks(0).summary(), "modules with diagnosis: 0, 2");
  EXPECT_EQ(v.blocks(1).kind(), "channel");
  EXPECT_EQ(v.blocks(1).summary(), "module 2 channel 1 input: error 1 (short circuit)");
  EXPECT_TRUE(v.texts().empty());
}

TEST(DiagnosisView, WhatCannotBeReadIsSaid) {
  EXPECT_EQ(decoded({0x08, 0x0C}, true, rs4_diagnosis_texts).error(),
            "2 bytes: shorter than the 6 standard ones");
  // a block claiming 16 bytes with 2 there: the standard part stays, the block is named
  const auto v = decoded({0x08, 0x0C, 0x00, 0x01, 0x09, 0x7A, 0x50, 0x01}, false, {});
  EXPECT_EQ(list(v.station_status()), (std::vector<std::string>{"Ext_Diag", "WD_On"}));
  EXPECT_EQ(v.blocks_size(), 0);
  EXPECT_NE(v.error().find("extended diagnosis block 1: "), std::string::npos) << v.error();
}

// tests/gsd/corpus/gateway_asi.gse (DPV1_Slave = 1, Ident_Number 0x0B4E) with the modules
// "Digital 4 byte in/out" (slot 0) and "Analog 2 words in" (slot 1). Its texts, as the file writes
// them: Unit_Diag_Bit(16) "AS-i voltage too low", Unit_Diag_Bit(17) "AS-i configuration error",
// Unit_Diag_Not_Bit(18) "gateway not in protected mode", Unit_Diag_Area 24-27 Value(2) "double
// address", and for blocks of type 129 (UnitDiagType = 129) X_Unit_Diag_Bit(8) "peripheral
// fault". The Slave_Diag, byte by byte:
//  - 08 0C 00 01 0B 4E: Ext_Diag; the always-1 bit + WD_On; master 1; ident 0x0B4E;
//  - 06 81 01 01 02 05: the device-related block (header 00 000110: 6 bytes with it), a DPV1
//    status PDU: type 0x81 (status message), slot 1, specifier 01 (appears), user data 02 05.
//    Bits counted after the header: bit 8 = bit 0 of the slot byte, set, in a block of type
//    0x81 = 129 ("peripheral fault"); bit 16 = bit 0 of the specifier byte, set ("AS-i voltage
//    too low"); 17 clear (no text); 18 clear ("gateway not in protected mode"); 24-27 = 2
//    ("double address"); 32-39 = 5, the file's X_Unit_Diag_Area outside a UnitDiagType, is not
//    read (docs/decisions.md gsd-unit-diag-types);
//  - 42 02: identifier block (01 000010: 2 bytes), bit 1: the module of slot 1;
//  - 81 41 27: channel block of module 1 (10 000001), input channel 1 (01 000001), error 7
//    upper limit exceeded (001 00111) [IEC 61158-6-3 Slave_Diag].
TEST(DiagnosisView, AGsdStationsDiagnosisInItsGsdsWords) {
  std::ifstream file(std::string(RS4SIM_GSD_CORPUS) + "/gateway_asi.gse", std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  auto device = gsd::parse(text.str(), "gateway_asi.gse");
  ASSERT_TRUE(device) << device.error().message;
  gsd::GsdStationSpec spec;
  spec.device = std::make_shared<const gsd::Device>(std::move(device).value());
  spec.modules = {{.name = "Digital 4 byte in/out"}, {.name = "Analog 2 words in"}};
  const auto v = decoded({0x08, 0x0C, 0x00, 0x01, 0x0B, 0x4E, 0x06, 0x81, 0x01, 0x01, 0x02, 0x05,
                          0x42, 0x02, 0x81, 0x41, 0x27},
                         true, gsd_diagnosis_texts(spec));
  EXPECT_EQ(v.ident_number(), 0x0B4EU);
  ASSERT_EQ(v.blocks_size(), 3) << v.error();
  EXPECT_EQ(v.blocks(0).kind(), "status");
  EXPECT_EQ(v.blocks(1).kind(), "identifier");
  EXPECT_EQ(v.blocks(2).kind(), "channel");
  EXPECT_EQ(list(v.texts()),
            (std::vector<std::string>{
                "peripheral fault", "AS-i voltage too low", "gateway not in protected mode",
                "double address",
                "slot 1 \"Analog 2 words in\" reports diagnosis",
                "slot 1 \"Analog 2 words in\" channel 1 input: error 7 (upper limit exceeded)"}));
  EXPECT_EQ(v.error(), "");
}

// A DP-V0 station whose GSD names the manufacturer-specific channel error type 16
// (Channel_Diag(16)), one module configured: 82 81 30 = module 2 (10 000010), output channel 1
// (10 000001), error 16 (001 10000): a slot with no module configured, the GSD's name; 80 81 31:
// module 0, error 17 that the GSD does not name [IEC 61158-6-3 Slave_Diag].
TEST(DiagnosisView, TheGsdsNameOfAManufacturersChannelError) {
  auto device = gsd::parse("#Profibus_DP\nIdent_Number = 0x1234\n12M_supp = 1\n"
                           "MaxTsdr_12M = 800\nChannel_Diag(16) = \"wire break at the valve\"\n",
                           "m.gsd");
  ASSERT_TRUE(device) << device.error().message;
  gsd::GsdStationSpec spec;
  spec.device = std::make_shared<const gsd::Device>(std::move(device).value());
  spec.modules = {{.name = "Valve 8"}};
  const auto v = decoded({0x08, 0x0C, 0x00, 0x02, 0x12, 0x34, 0x82, 0x81, 0x30, 0x80, 0x81, 0x31},
                         false, gsd_diagnosis_texts(spec));
  EXPECT_EQ(list(v.texts()),
            (std::vector<std::string>{
                "slot 2 (no module configured there) channel 1 output: error 16 (wire break at "
                "the valve)",
                "slot 0 \"Valve 8\" channel 1 output: error 17 (manufacturer specific)"}));
}

}  // namespace
}  // namespace rs4sim::rpc
