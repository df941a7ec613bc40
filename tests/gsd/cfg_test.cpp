// Cfg identifiers ([IEC 61158-6-3 Chk_Cfg/Get_Cfg]): known answers from the cited examples.
#include "gsd/cfg.h"

#include <gtest/gtest.h>

#include <vector>

namespace rs4sim::gsd {
namespace {

TEST(GsdCfg, CompactIdentifiers) {
  const std::vector<std::uint8_t> cfg{
      0x10,  // +0 compact: 01 input, length 0+1 = 1 byte
      0x20,  // +1 compact: 10 output, 1 byte
      0x51,  // +2 compact: b6 words, 01 input, 2 words = 4 bytes
      0xB4,  // +3 compact: b7 consistent, 11 in+out, 5 bytes each
  };
  auto l = decode_cfg(cfg);
  ASSERT_TRUE(l);
  ASSERT_EQ(l.value().identifiers.size(), 4U);
  EXPECT_EQ(l.value().input_bytes, 1U + 4U + 5U);
  EXPECT_EQ(l.value().output_bytes, 1U + 5U);
  EXPECT_TRUE(l.value().identifiers[3].input_consistent);
  EXPECT_FALSE(l.value().identifiers[2].input_consistent);
}

TEST(GsdCfg, SpecialFormatProfisafeModule) {
  // WAGO 75x-661 ([IEC 61158-6-3 Chk_Cfg/Get_Cfg] example): in/out, 4 manufacturer bytes, 5 bytes
  // out, 5 bytes in.
  const std::vector<std::uint8_t> cfg{
      0xC4,                    // +0 special: 11 = output then input length byte, 4 manuf. bytes
      0x84,                    // +1 output length: b7 consistent, 4+1 = 5 bytes
      0x84,                    // +2 input length: b7 consistent, 5 bytes
      0x05, 0x0A, 0x05, 0x0A,  // +3..+6 manufacturer-specific
  };
  auto l = decode_cfg(cfg);
  ASSERT_TRUE(l);
  ASSERT_EQ(l.value().identifiers.size(), 1U);
  const auto& id = l.value().identifiers[0];
  EXPECT_EQ(id.size, 7U);
  EXPECT_EQ(id.input_bytes, 5U);
  EXPECT_EQ(id.output_bytes, 5U);
  EXPECT_TRUE(id.output_consistent);
  EXPECT_EQ(id.manufacturer_bytes, 4U);
}

TEST(GsdCfg, SpecialFormatCp5613Example) {
  // [IEC 61158-6-3 Chk_Cfg/Get_Cfg]: 0xC3 0xCF 0xC7 m m m = outputs 16 words consistent, inputs 8
  // words consistent.
  const std::vector<std::uint8_t> cfg{0xC3, 0xCF, 0xC7, 0x01, 0x02, 0x03, 0x00};
  auto l = decode_cfg(cfg);
  ASSERT_TRUE(l);
  EXPECT_EQ(l.value().output_bytes, 32U);
  EXPECT_EQ(l.value().input_bytes, 16U);
  ASSERT_EQ(l.value().identifiers.size(), 2U);  // + 0x00 empty slot
  EXPECT_EQ(l.value().identifiers[1].offset, 6U);
}

TEST(GsdCfg, SingleInputLengthByteAnd64ByteMaximum) {
  const std::vector<std::uint8_t> cfg{0x40, 0x3F, 0x80, 0x7F};  // 64 bytes in; 64 words out
  auto l = decode_cfg(cfg);
  ASSERT_TRUE(l);
  EXPECT_EQ(l.value().input_bytes, 64U);
  EXPECT_EQ(l.value().output_bytes, 128U);
}

TEST(GsdCfg, ManufacturerCount15MeansNoBytes) {
  auto l = decode_cfg(std::vector<std::uint8_t>{0x4F, 0x00});
  ASSERT_TRUE(l);
  EXPECT_EQ(l.value().identifiers[0].size, 2U);
  EXPECT_EQ(l.value().input_bytes, 1U);
}

TEST(GsdCfg, MalformedIdentifiers) {
  const struct {
    std::vector<std::uint8_t> cfg;
    const char* message;
  } cases[] = {
      {{}, "Cfg data is empty"},
      {{0x40}, "Cfg identifier at byte 0: input length byte missing"},
      {{0x10, 0x80}, "Cfg identifier at byte 1: output length byte missing"},
      {{0xC0, 0x84}, "Cfg identifier at byte 0: input length byte missing"},
      {{0x02, 0x01}, "Cfg identifier at byte 0: manufacturer-specific bytes missing"},
  };
  for (const auto& c : cases) {
    auto l = decode_cfg(c.cfg);
    ASSERT_FALSE(l) << c.message;
    EXPECT_EQ(l.error().code, GsdError::kBadCfg);
    EXPECT_EQ(l.error().message, c.message);
  }
}

}  // namespace
}  // namespace rs4sim::gsd
