// The set file (rs4/param_doc/set_file.h): the format-2 trailer byte by byte, its CRC-32 from
// zlib's crc32() (an implementation apart from the code under test), every single-byte flip
// of a format-2 file refused, a format-1 file read with its warning.
#include "rs4/param_doc/set_file.h"
#include "rs4/scanner/parameter_codec.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <vector>

namespace rs4sim::rs4::param_doc {
namespace {

std::vector<std::uint8_t> factory_encoding() {
  return scanner::encode(scanner::factory_default());
}

std::uint32_t zlib_crc(const std::vector<std::uint8_t>& bytes) {
  return static_cast<std::uint32_t>(
      crc32(0L, bytes.data(), static_cast<uInt>(bytes.size())));
}

TEST(SetFile, Format2IsTheEncodingThenTheTrailer) {
  const auto encoding = factory_encoding();
  ASSERT_EQ(encoding.size(), 8507u);
  const auto file = set_file(encoding);
  ASSERT_EQ(file.size(), 8516u);
  EXPECT_TRUE(std::equal(encoding.begin(), encoding.end(), file.begin()));
  std::vector<std::uint8_t> covered(file.begin(), file.begin() + 8512);
  const auto crc = zlib_crc(covered);
  const std::vector<std::uint8_t> trailer = {
      0x52, 0x53, 0x34, 0x46,  // 8507 "RS4F"
      0x02,                    // 8511 file format 2
      static_cast<std::uint8_t>(crc >> 24), static_cast<std::uint8_t>(crc >> 16),
      static_cast<std::uint8_t>(crc >> 8), static_cast<std::uint8_t>(crc),  // 8512 CRC-32, BE
  };
  EXPECT_EQ(std::vector<std::uint8_t>(file.begin() + 8507, file.end()), trailer);
  const auto read = read_set_file(file);
  ASSERT_TRUE(read.bytes) << read.error;
  EXPECT_EQ(read.bytes->format, 2u);
  EXPECT_EQ(read.bytes->encoding, encoding);
  EXPECT_EQ(read.bytes->warning, "");
}

TEST(SetFile, EverySingleByteFlipOfAFormat2FileIsRefused) {
  const auto good = set_file(factory_encoding());
  std::size_t refused = 0;
  for (std::size_t i = 0; i < good.size(); ++i) {
    for (const unsigned mask : {0x01U, 0x80U, 0xFFU}) {
      auto bad = good;
      bad[i] = static_cast<std::uint8_t>(bad[i] ^ mask);
      const auto read = read_set_file(bad);
      if (!read.bytes) ++refused;
      EXPECT_FALSE(read.bytes) << "byte " << i << " ^ " << mask;
    }
  }
  EXPECT_EQ(refused, 3 * 8516u);
}

TEST(SetFile, RefusalsSayWhy) {
  auto file = set_file(factory_encoding());
  file[100] = static_cast<std::uint8_t>(file[100] ^ 0x04U);
  const auto read = read_set_file(file);
  EXPECT_EQ(read.error.substr(0, 27), "damaged: its CRC-32 says 0x");
  file[100] = static_cast<std::uint8_t>(file[100] ^ 0x04U);
  file[8507] = 'X';
  EXPECT_EQ(read_set_file(file).error, "damaged: no \"RS4F\" trailer at byte 8507");
  EXPECT_EQ(read_set_file(std::vector<std::uint8_t>(10)).error,
            "10 bytes, not a set file (8507 bytes in format 1, 8516 in format 2)");
  // A later format with a sound CRC: named, not taken for damage.
  auto later = factory_encoding();
  later.insert(later.end(), {0x52, 0x53, 0x34, 0x46, 0x03});
  const auto crc = zlib_crc(later);
  for (const int shift : {24, 16, 8, 0}) later.push_back(static_cast<std::uint8_t>(crc >> shift));
  EXPECT_EQ(read_set_file(later).error, "set file format 3, this rs4sim reads formats 1 and 2");
}

TEST(SetFile, Format1IsReadWithAWarning) {
  const auto read = read_set_file(factory_encoding());
  ASSERT_TRUE(read.bytes);
  EXPECT_EQ(read.bytes->format, 1u);
  EXPECT_EQ(read.bytes->encoding, factory_encoding());
  EXPECT_NE(read.bytes->warning.find("carries no checksum"), std::string::npos);
}

}  // namespace
}  // namespace rs4sim::rs4::param_doc
