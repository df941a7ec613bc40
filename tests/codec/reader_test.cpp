// codec::Reader on fixed bytes: field order, byte order, and the latched first error.
#include "codec/reader.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>

namespace rs4sim::codec {
namespace {

TEST(ReaderTest, ReadsBigAndLittleEndianFieldsInOrder) {
  const std::array<std::uint8_t, 13> bytes{
      0x7E,                    // 0     u8
      0x12, 0x34,              // 1-2   u16 BE = 0x1234
      0x34, 0x12,              // 3-4   u16 LE = 0x1234
      0xDE, 0xAD, 0xBE, 0xEF,  // 5-8   u32 BE = 0xDEADBEEF
      0xEF, 0xBE, 0xAD, 0xDE,  // 9-12  u32 LE = 0xDEADBEEF
  };
  Reader r(bytes);
  EXPECT_EQ(r.u8(), 0x7E);
  EXPECT_EQ(r.u16_be(), 0x1234);
  EXPECT_EQ(r.u16_le(), 0x1234);
  EXPECT_EQ(r.u32_be(), 0xDEADBEEFU);
  EXPECT_EQ(r.u32_le(), 0xDEADBEEFU);
  EXPECT_TRUE(r.at_end());
  EXPECT_TRUE(r.ok());
  EXPECT_FALSE(r.error());
}

TEST(ReaderTest, BytesSkipAndRestAreViewsIntoTheInput) {
  const std::array<std::uint8_t, 6> bytes{
      0x01, 0x02,  // 0-1  skipped
      0x03, 0x04,  // 2-3  bytes(2)
      0x05, 0x06,  // 4-5  rest()
  };
  Reader r(bytes);
  r.skip(2);
  EXPECT_EQ(r.position(), 2U);
  const auto two = r.bytes(2);
  ASSERT_EQ(two.size(), 2U);
  EXPECT_EQ(two.data(), bytes.data() + 2);
  EXPECT_EQ(r.remaining(), 2U);
  const auto rest = r.rest();
  EXPECT_EQ(rest.size(), 2U);
  EXPECT_EQ(rest[1], 0x06);
  EXPECT_TRUE(r.rest().empty());  // reading nothing at the end is no error
  EXPECT_TRUE(r.ok());
}

TEST(ReaderTest, ReadPastTheEndReturnsZeroAndKeepsTheFirstError) {
  const std::array<std::uint8_t, 3> bytes{
      0xAB,        // 0    u8
      0xCD, 0xEF,  // 1-2  only two of the four bytes a u32 needs
  };
  Reader r(bytes);
  EXPECT_EQ(r.u8(), 0xAB);
  EXPECT_EQ(r.u32_be(), 0U);  // does not fit: zero, error latched
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.u8(), 0);  // the two bytes left are not handed out after the error
  EXPECT_EQ(r.u16_le(), 0);
  EXPECT_TRUE(r.bytes(1).empty());
  EXPECT_EQ(r.remaining(), 0U);
  EXPECT_EQ(r.error(), BufferError::kReadPastEnd);
}

TEST(ReaderTest, CopyToFillsCharArraysAndZerosAfterAnError) {
  const std::array<std::uint8_t, 3> bytes{'R', 'S', '4'};
  Reader r(bytes);
  std::array<char, 3> id{};
  r.copy_to(id);
  EXPECT_EQ(id, (std::array<char, 3>{'R', 'S', '4'}));
  std::array<char, 1> more{'x'};
  r.copy_to(more);
  EXPECT_EQ(more[0], '\0');
  EXPECT_FALSE(r.ok());
}

TEST(ReaderTest, U16BeArrayReadsAllOrNothing) {
  const std::array<std::uint8_t, 5> bytes{
      0x00, 0x01,  // 0-1  value 0 = 1
      0x02, 0x10,  // 2-3  value 1 = 0x0210 (528, the last segment)
      0xFF,        // 4    half a value
  };
  Reader r(bytes);
  std::array<std::uint16_t, 2> two{};
  r.u16_be_array(two);
  EXPECT_EQ(two, (std::array<std::uint16_t, 2>{1, 528}));
  std::array<std::uint16_t, 1> one{7};
  r.u16_be_array(one);
  EXPECT_EQ(one[0], 0);
  EXPECT_FALSE(r.ok());
}

TEST(ReaderTest, UintBeReadsVariableWidthValues) {
  const std::array<std::uint8_t, 6> bytes{
      0x12, 0x34, 0x56,  // 0-2  24-bit CRC2 = 0x123456
      0xAB, 0xCD,        // 3-4  16-bit = 0xABCD
      0xEF,              // 5    left over
  };
  Reader r(bytes);
  EXPECT_EQ(r.uint_be(3), 0x123456U);
  EXPECT_EQ(r.uint_be(2), 0xABCDU);
  EXPECT_EQ(r.uint_be(0), 0U);
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.uint_be(5), 0U);  // wider than 32 bits: an error, not a truncated value
  EXPECT_FALSE(r.ok());
}

TEST(ReaderTest, FailLatchesACallersError) {
  const std::array<std::uint8_t, 2> bytes{0x05, 0x00};  // a length byte 5 that cannot be right
  Reader r(bytes);
  if (r.u8() > r.remaining()) r.fail();
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.u8(), 0);
}

TEST(ReaderTest, IsUsableAtCompileTime) {
  constexpr auto kValue = [] {
    constexpr std::array<std::uint8_t, 2> kBytes{0x01, 0xF4};  // 500, F_Dest_Add of station 0
    Reader r(kBytes);
    return r.u16_be();
  }();
  static_assert(kValue == 500);
}

}  // namespace
}  // namespace rs4sim::codec
