// CRC1 (F_Par_CRC) known answers, [IEC 61784-3-3 CRC1] (VERIFIED vectors) and
// [RS4 manual §6.2, §6.3] (the manual's dialog values give 0x5696 by the verified rule).
#include "profisafe/crc.h"
#include "profisafe/f_parameters.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>

namespace rs4sim::profisafe {
namespace {

using Block8 = std::array<std::uint8_t, 8>;

TEST(ProfisafeCrc1, PublishedVector1) {
  const Block8 b{
      0x08,        // 0 F_Prm_Flag1: SIL code 2 (SIL3), F_CRC_Length 0 (3-byte)
      0x40,        // 1 F_Prm_Flag2: F_Par_Version 1, F_Block_ID 0
      0x00, 0x01,  // 2 F_Source_Add = 1
      0x00, 0x01,  // 4 F_Dest_Add = 1
      0x00, 0x96,  // 6 F_WD_Time = 150 ms
  };
  EXPECT_EQ(crc1(b), 48021);  // 0xBB95
}

TEST(ProfisafeCrc1, PublishedVector2) {
  const Block8 b{
      0x04,        // 0 F_Prm_Flag1: SIL code 1 (SIL2), F_CRC_Length 0
      0x40,        // 1 F_Prm_Flag2: F_Par_Version 1
      0x00, 0x01,  // 2 F_Source_Add = 1
      0x00, 0x01,  // 4 F_Dest_Add = 1
      0x01, 0xF4,  // 6 F_WD_Time = 500 ms
  };
  EXPECT_EQ(crc1(b), 37411);  // 0x9223
}

TEST(ProfisafeCrc1, PublishedVector3WithIParCrcFedFirst) {
  const Block8 b{
      0x08,        // 0 F_Prm_Flag1: SIL3
      0x48,        // 1 F_Prm_Flag2: F_Par_Version 1, F_Block_ID 1 (F_iPar_CRC present)
      0x00, 0x01,  // 2 F_Source_Add = 1
      0x00, 0x01,  // 4 F_Dest_Add = 1
      0x00, 0x7D,  // 6 F_WD_Time = 125 ms
  };
  EXPECT_EQ(crc1(b, 1132081116u), 17033);  // 0x4289
  EXPECT_NE(crc1(b), 17033);               // the iPar CRC really is covered
}

TEST(ProfisafeCrc1, ManualDialogValuesGive0x5696) {
  // [RS4 manual §6.2, §6.3]: SIL2, 2-byte CRC, V1, block 0, src 2002, dst 604, WD 500.
  const Block8 b{0x14, 0x00, 0x07, 0xD2, 0x02, 0x5C, 0x01, 0xF4};
  EXPECT_EQ(crc1(b), 0x5696);
}

TEST(ProfisafeCrc1, FromStructMatchesFromBytes) {
  FParameters p;  // vector 2 as a struct
  p.sil = Sil::kSil2;
  p.crc_length = CrcLength::k3Byte;
  p.par_version = 1;
  p.source_add = 1;
  p.dest_add = 1;
  p.wd_time_ms = 500;
  EXPECT_EQ(crc1(p), 0x9223);
  p.block_id = 1;
  p.sil = Sil::kSil3;
  p.wd_time_ms = 125;
  p.ipar_crc = 1132081116u;
  EXPECT_EQ(crc1(p), 0x4289);
}

TEST(ProfisafeCrc, TableMatchesBitwiseDefinition) {
  // The table-driven CRC against the bitwise definition (MSB first, no reflection).
  auto bitwise = [](unsigned width, std::uint32_t poly, std::uint32_t reg, std::uint8_t byte) {
    const std::uint32_t top = 1u << (width - 1), mask = (1u << width) - 1;
    reg ^= static_cast<std::uint32_t>(byte) << (width - 8);
    for (int i = 0; i < 8; ++i) reg = ((reg & top) ? (reg << 1) ^ poly : reg << 1) & mask;
    return reg;
  };
  std::uint32_t r16 = 0x1234, r24 = 0xABCDEF, t16 = r16, t24 = r24;
  for (unsigned v = 0; v < 256; ++v) {
    const std::array<std::uint8_t, 1> b{static_cast<std::uint8_t>(v * 37 + 11)};
    r16 = bitwise(16, kCrc16Poly, r16, b[0]);
    r24 = bitwise(24, kCrc24Poly, r24, b[0]);
    t16 = crc16().update(t16, b);
    t24 = crc24().update(t24, b);
    ASSERT_EQ(t16, r16) << v;
    ASSERT_EQ(t24, r24) << v;
  }
}

}  // namespace
}  // namespace rs4sim::profisafe
