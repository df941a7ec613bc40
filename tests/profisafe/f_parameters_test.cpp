// F-parameter block: parsing, encoding, validation against the RS4 profile and the status
// PDU `05 81 00 00 nn` ([IEC 61784-3-3 F-Parameters], [RS4 manual §6.2, §6.3],
// [RS4 manual table 6.3-1]).
#include "profisafe/f_parameters.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

namespace rs4sim::profisafe {
namespace {

using Bytes = std::vector<std::uint8_t>;

// The RS4 factory defaults at DP address 4: F_Check_SeqNr 0, SIL2, 2-byte CRC, V1,
// block 0, F_Source_Add 1, F_Dest_Add 504, F_WD_Time 10 ms.
const Bytes kRs4Default{
    0x14,        // 0 F_Prm_Flag1: b2-3 F_SIL = 1 (SIL2), b4-5 F_CRC_Length = 1 (2-byte)
    0x00,        // 1 F_Prm_Flag2: F_Block_ID 0, F_Par_Version 0 (V1)
    0x00, 0x01,  // 2 F_Source_Add = 1
    0x01, 0xF8,  // 4 F_Dest_Add = 504 = 500 + address 4
    0x00, 0x0A,  // 6 F_WD_Time = 10 ms
    0x83, 0xA9,  // 8 F_Par_CRC = CRC1 (bitwise reference of the VERIFIED rule,
                 // [IEC 61784-3-3 CRC1])
};

TEST(ProfisafeFParameters, ParsesPublishedVector2) {
  const Bytes b{
      0x04,        // 0 F_Prm_Flag1: F_SIL = 1 (SIL2), F_CRC_Length = 0 (3-byte, V2)
      0x40,        // 1 F_Prm_Flag2: F_Par_Version = 1
      0x00, 0x01,  // 2 F_Source_Add = 1
      0x00, 0x01,  // 4 F_Dest_Add = 1
      0x01, 0xF4,  // 6 F_WD_Time = 500
      0x92, 0x23,  // 8 F_Par_CRC = 37411 ([IEC 61784-3-3 CRC1] vector)
  };
  const auto p = parse_f_parameters(b);
  ASSERT_TRUE(p) << p.error().message();
  EXPECT_FALSE(p.value().check_seqnr);
  EXPECT_FALSE(p.value().check_ipar);
  EXPECT_EQ(p.value().sil, Sil::kSil2);
  EXPECT_EQ(p.value().crc_length, CrcLength::k3Byte);
  EXPECT_EQ(p.value().block_id, 0);
  EXPECT_EQ(p.value().par_version, 1);
  EXPECT_EQ(p.value().source_add, 1);
  EXPECT_EQ(p.value().dest_add, 1);
  EXPECT_EQ(p.value().wd_time_ms, 500);
  EXPECT_EQ(p.value().par_crc, 0x9223);
  EXPECT_EQ(p.value().par_crc, crc1(p.value()));  // the carried CRC1 is the computed one
}

TEST(ProfisafeFParameters, ParsesEveryFlagBit) {
  const Bytes b{
      0x2F,  // 0 F_Prm_Flag1: b0 F_Check_SeqNr, b1 F_Check_iPar, F_SIL 3 (NoSIL), F_CRC_Length 2
      0x78,  // 1 F_Prm_Flag2: F_Block_ID 7 (b3-5), F_Par_Version 1 (b6)
      0xFF, 0xFE,  // 2 F_Source_Add = 65534
      0x12, 0x34,  // 4 F_Dest_Add = 0x1234
      0x03, 0xE8,  // 6 F_WD_Time = 1000
      0xAB, 0xCD,  // 8 F_Par_CRC = 0xABCD (as received)
  };
  const auto p = parse_f_parameters(b);
  ASSERT_TRUE(p);
  EXPECT_TRUE(p.value().check_seqnr);
  EXPECT_TRUE(p.value().check_ipar);
  EXPECT_EQ(p.value().sil, Sil::kNoSil);
  EXPECT_EQ(p.value().crc_length, CrcLength::k4Byte);
  EXPECT_EQ(p.value().block_id, 7);
  EXPECT_EQ(p.value().par_version, 1);
  EXPECT_EQ(p.value().source_add, 65534);
  EXPECT_EQ(p.value().dest_add, 0x1234);
  EXPECT_EQ(p.value().wd_time_ms, 1000);
  EXPECT_EQ(p.value().par_crc, 0xABCD);
}

TEST(ProfisafeFParameters, EncodesRs4DefaultsToFixedBytes) {
  FParameters p;  // defaults are the RS4's
  const auto b = encode_f_parameters(p);
  EXPECT_EQ(Bytes(b.begin(), b.end()), kRs4Default);
  const auto back = parse_f_parameters(b);
  ASSERT_TRUE(back);
  p.par_crc = 0x83A9;
  EXPECT_EQ(back.value(), p);
}

TEST(ProfisafeFParameters, EncodesManualDialogValues) {
  FParameters p;
  p.source_add = 2002;
  p.dest_add = 604;
  p.wd_time_ms = 500;
  const Bytes expected{0x14, 0x00, 0x07, 0xD2, 0x02, 0x5C, 0x01, 0xF4, 0x56, 0x96};
  const auto b = encode_f_parameters(p);
  EXPECT_EQ(Bytes(b.begin(), b.end()), expected);
}

TEST(ProfisafeFParameters, RawEncodingKeepsAGivenWrongCrc) {
  FParameters p;
  p.par_crc = 0x1111;
  const auto b = encode_f_parameters_raw(p);
  EXPECT_EQ(b[8], 0x11);
  EXPECT_EQ(b[9], 0x11);
}

TEST(ProfisafeFParameters, RejectsWrongSizes) {
  for (std::size_t n : {0u, 1u, 9u, 11u, 14u}) {
    const Bytes b(n, 0);
    const auto p = parse_f_parameters(b);
    ASSERT_FALSE(p) << n;
    EXPECT_EQ(p.error(), ProfisafeError::kFParamsWrongSize);
  }
}

TEST(ProfisafeFParameters, RejectsReservedBits) {
  for (const auto& [at, bit] : {std::pair{0, 0x40}, {0, 0x80}, {1, 0x01}, {1, 0x02}, {1, 0x04}}) {
    Bytes b = kRs4Default;
    b[static_cast<std::size_t>(at)] =
        static_cast<std::uint8_t>(b[static_cast<std::size_t>(at)] | bit);
    const auto p = parse_f_parameters(b);
    ASSERT_FALSE(p) << at << " " << bit;
    EXPECT_EQ(p.error(), ProfisafeError::kFParamsReservedBits);
  }
}

TEST(ProfisafeFParameters, IParCrcOnlyForV2) {
  EXPECT_EQ(parse_f_parameters(kRs4Default, 5u).error(), ProfisafeError::kFParamsIParCrcNeedsV2);
}

TEST(ProfisafeFParameters, ErrorCodesHaveMessages) {
  const std::error_code ec = ProfisafeError::kFParamsWrongSize;
  EXPECT_EQ(ec.category().name(), std::string("rs4sim.profisafe"));
  EXPECT_EQ(ec.message(), "F-parameter block is not 10 bytes");
  // The RS4's diagnosis numbers and their messages: tests/rs4/safety/diagnosis_test.cpp.
  EXPECT_STREQ(to_string(FParameterFault::kCrc1Mismatch), "wrong CRC1 over the F-parameters");
}

}  // namespace
}  // namespace rs4sim::profisafe
