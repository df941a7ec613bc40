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
#include "rpc/diagnosis_view.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace rs4sim::rpc
