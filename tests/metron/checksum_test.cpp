// The METRON checksum: one's complement of the byte sum [METRON manual "No node"], in the
// two readings the manual leaves open (metron/checksum.h).
#include "metron/checksum.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace rs4sim::metron {
namespace {

using R = ChecksumReading;

std::uint8_t ck(std::vector<std::uint8_t> b, R r) { return checksum(b, r); }

TEST(MetronChecksum, NoBytesIsFF) {
  EXPECT_EQ(ck({}, R::kModulo256), 0xFF);
  EXPECT_EQ(ck({}, R::kEndAroundCarry), 0xFF);
}

TEST(MetronChecksum, SumBelow256ReadingsAgree) {
  // Request OSSD status (EXTENSION code 0x0C): ~0x0C = 0xF3.
  EXPECT_EQ(ck({0x0C}, R::kModulo256), 0xF3);
  EXPECT_EQ(ck({0x0C}, R::kEndAroundCarry), 0xF3);
  // Request instantaneous measurements 0x0A, fields 01 02 03: sum 0x10 -> 0xEF.
  EXPECT_EQ(ck({0x0A, 0x01, 0x02, 0x03}, R::kModulo256), 0xEF);
  EXPECT_EQ(ck({0x0A, 0x01, 0x02, 0x03}, R::kEndAroundCarry), 0xEF);
}

TEST(MetronChecksum, SumAbove255ReadingsDiffer) {
  // 0x0A + 0x80 + 0x90 = 0x11A: modulo 256 -> 0x1A -> ~ = 0xE5;
  // end-around carry 0x1A + 1 = 0x1B -> ~ = 0xE4.
  EXPECT_EQ(ck({0x0A, 0x80, 0x90}, R::kModulo256), 0xE5);
  EXPECT_EQ(ck({0x0A, 0x80, 0x90}, R::kEndAroundCarry), 0xE4);
  // 0xFF + 0xFF = 0x1FE: modulo -> ~0xFE = 0x01; end-around 0xFE + 1 = 0xFF -> 0x00.
  EXPECT_EQ(ck({0xFF, 0xFF}, R::kModulo256), 0x01);
  EXPECT_EQ(ck({0xFF, 0xFF}, R::kEndAroundCarry), 0x00);
}

TEST(MetronChecksum, ModuloReadingMakesTheSumFF) {
  const std::vector<std::uint8_t> body{0x0B, 0x18, 0x00, 0x00, 0x0A, 0x14};
  unsigned sum = checksum(body, R::kModulo256);
  for (auto b : body) sum += b;
  EXPECT_EQ(sum & 0xFFU, 0xFFU);
}

}  // namespace
}  // namespace rs4sim::metron
