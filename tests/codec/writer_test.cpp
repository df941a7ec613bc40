// codec::Writer (fixed buffer) and codec::Appender (growing container) on fixed bytes.
#include "codec/writer.h"

#include <boost/container/static_vector.hpp>
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

namespace rs4sim::codec {
namespace {

TEST(WriterTest, WritesBigAndLittleEndianFieldsInOrder) {
  std::array<std::uint8_t, 13> buffer{};
  Writer w(buffer);
  w.u8(0x7E);
  w.u16_be(0x1234);
  w.u16_le(0x1234);
  w.u32_be(0xDEADBEEF);
  w.u32_le(0xDEADBEEF);
  EXPECT_TRUE(w.ok());
  EXPECT_EQ(w.size(), 13U);
  EXPECT_EQ(buffer, (std::array<std::uint8_t, 13>{
                        0x7E,                    // 0     u8
                        0x12, 0x34,              // 1-2   u16 BE
                        0x34, 0x12,              // 3-4   u16 LE
                        0xDE, 0xAD, 0xBE, 0xEF,  // 5-8   u32 BE
                        0xEF, 0xBE, 0xAD, 0xDE,  // 9-12  u32 LE
                    }));
}

TEST(WriterTest, OverflowDropsTheWriteAndKeepsTheFirstError) {
  std::array<std::uint8_t, 3> buffer{};
  Writer w(buffer);
  w.u16_be(0xA1B2);
  w.u16_be(0xC3D4);  // needs 2, 1 left: dropped, error latched
  w.u8(0xE5);        // would fit, but the writer has failed
  EXPECT_FALSE(w.ok());
  EXPECT_EQ(w.error(), BufferError::kWritePastEnd);
  EXPECT_EQ(w.size(), 2U);
  EXPECT_EQ(buffer, (std::array<std::uint8_t, 3>{0xA1, 0xB2, 0x00}));
}

TEST(WriterTest, UintBeWritesTheLowBytesHighFirst) {
  std::array<std::uint8_t, 8> buffer{};
  Writer w(buffer);
  w.uint_be(0x00123456, 3);  // 0-2  24-bit CRC2
  w.uint_be(0xABCD, 2);      // 3-4
  EXPECT_TRUE(w.ok());
  EXPECT_EQ(buffer, (std::array<std::uint8_t, 8>{0x12, 0x34, 0x56, 0xAB, 0xCD, 0, 0, 0}));
  w.uint_be(0, 5);  // wider than 32 bits: an error, nothing written
  EXPECT_FALSE(w.ok());
  EXPECT_EQ(w.size(), 5U);
}

TEST(AppenderTest, AppendsUpToTheLimit) {
  boost::container::static_vector<std::uint8_t, 8> out{0x68};  // one byte already there
  Appender a(out, 4);
  const std::array<std::uint8_t, 2> data{0x01, 0x02};
  a.bytes(data);  // 1-2
  a.u8(0x03);     // 3 -> size 4 = limit
  EXPECT_TRUE(a.ok());
  a.u8(0x04);  // beyond the limit
  EXPECT_FALSE(a.ok());
  EXPECT_EQ(out.size(), 4U);
  EXPECT_EQ(out[3], 0x03);
}

TEST(AppenderTest, DefaultLimitIsTheContainersCapacity) {
  boost::container::static_vector<std::uint8_t, 3> out;
  Appender a(out);
  a.u16_le(0x0201);
  a.u16_le(0x0403);  // 4 bytes into a 3-byte vector
  EXPECT_FALSE(a.ok());
  EXPECT_EQ(out.size(), 2U);
  std::vector<std::uint8_t> grows;
  Appender g(grows);
  const std::array<char, 4> magic{'R', 'S', '4', 'P'};
  g.copy_from(magic);
  EXPECT_TRUE(g.ok());
  EXPECT_EQ(grows, (std::vector<std::uint8_t>{'R', 'S', '4', 'P'}));
}

}  // namespace
}  // namespace rs4sim::codec
