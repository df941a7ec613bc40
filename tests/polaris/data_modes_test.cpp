#include "polaris/data_modes.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <initializer_list>
#include <vector>

namespace rs4sim::polaris {
namespace {

using Words = std::vector<std::uint16_t>;

std::vector<std::uint8_t> scene(std::uint16_t beams, std::initializer_list<std::uint16_t> blocked) {
  std::vector<std::uint8_t> s(beams, 0);
  for (const std::uint16_t b : blocked) s[b - 1U] = 1;
  return s;
}

Options pli02_127(DataMode mode) {
  Options o;
  o.family = Family::kPli02;
  o.beams = 127;
  o.mode = mode;
  return o;
}

TEST(Measurement, Bits485MbOfTheScreenshot) {
  // P2 [Polaris manual §7.4.3]: 127 beams, words 4/5 = 807F F03F, the rest FFFF. With
  // beam 16w+b+1 at bit b (LSB first, DECISION) that is beams 72-79 and 87-92 blocked.
  std::vector<std::uint8_t> s(127, 0);
  for (std::uint16_t b = 72; b <= 79; ++b) s[b - 1U] = 1;
  for (std::uint16_t b = 87; b <= 92; ++b) s[b - 1U] = 1;
  EXPECT_EQ(data_words(pli02_127(DataMode::k485Mb), s),
            (Words{0xFFFF, 0xFFFF, 0xFFFF, 0xFFFF, 0x807F, 0xF03F, 0xFFFF, 0xFFFF}));
}

TEST(Measurement, MsbFirstIsTheOtherReading) {
  Options o = pli02_127(DataMode::k485Mb);
  o.bit_order = BitOrder::kMsbFirst;
  const Words w = data_words(o, scene(127, {1, 16, 127}));
  EXPECT_EQ(w[0], 0x7FFE);  // beam 1 at bit 15, beam 16 at bit 0
  EXPECT_EQ(w[7], 0xFFFD);  // beam 127 at bit 1; beam 128 (padding) stays 1
}

TEST(Measurement, Fl4OfTheTextExample) {
  // P4 [Polaris manual §8.2.3]: objects 9-13 and 25-34; last = last interrupted beam.
  Options o;
  o.beams = 40;
  o.mode = DataMode::kFl4;
  std::vector<std::uint8_t> s(40, 0);
  for (std::uint16_t b = 9; b <= 13; ++b) s[b - 1U] = 1;
  for (std::uint16_t b = 25; b <= 34; ++b) s[b - 1U] = 1;
  EXPECT_EQ(data_words(o, s), (Words{9, 13, 25, 34, 0, 0, 0, 0, 9, 34}));
  o.mode = DataMode::kFl1;
  EXPECT_EQ(data_words(o, s), (Words{9, 34}));
  o.mode = DataMode::kFl10;
  EXPECT_EQ(data_words(o, s).size(), 22U);
  EXPECT_EQ(block_words(o), 22U);
}

TEST(Measurement, MoreObjectsThanPairsKeepsTheFirst) {
  Options o;
  o.beams = 16;
  o.mode = DataMode::kFl4;
  EXPECT_EQ(data_words(o, scene(16, {1, 3, 5, 7, 9, 11})), (Words{1, 1, 3, 3, 5, 5, 7, 7, 1, 11}));
}

TEST(Measurement, ReverseNumbersFromTheFarCap) {
  Options o;
  o.beams = 16;
  o.direction = ScanDirection::kReverse;
  EXPECT_EQ(find_objects(o, scene(16, {1, 2, 10})), (std::vector<Object>{{7, 7}, {15, 16}}));
}

TEST(Measurement, EmptySceneIsZeroPairsAndFreeBits) {
  Options o;
  o.mode = DataMode::kFl1;
  EXPECT_EQ(data_words(o, scene(16, {})), (Words{0, 0}));
  o.mode = DataMode::k485Mb;
  EXPECT_EQ(data_words(o, scene(16, {})), (Words{0xFFFF}));
}

}  // namespace
}  // namespace rs4sim::polaris
