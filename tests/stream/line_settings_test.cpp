#include "stream/line_settings.h"

#include <gtest/gtest.h>

using namespace rs4sim::stream;
using namespace std::chrono_literals;

TEST(LineSettings, BitsPerCharacterCountStartParityAndStop) {
  EXPECT_EQ(bits_per_character({115200, 8, Parity::kNone, 1}), 10U);  // GridScan 8N1
  EXPECT_EQ(bits_per_character({19200, 8, Parity::kEven, 1}), 11U);   // METRON slave 8E1
  EXPECT_EQ(bits_per_character({9600, 7, Parity::kOdd, 2}), 11U);
}

TEST(LineSettings, CharacterTimeAtModbusRates) {
  // 19200 8N1: one character is 10 bits = 520.833 µs; t3.5 = 1822.9 µs, rounded up.
  const LineSettings s{19200, 8, Parity::kNone, 1};
  EXPECT_EQ(character_time(s), 520834ns);
  EXPECT_EQ(character_time(s, 3.5), 1822917ns);
  EXPECT_EQ(character_time({115200, 8, Parity::kNone, 1}), 86806ns);
}

TEST(LineSettings, FormatsAndParses) {
  EXPECT_EQ(to_string({19200, 8, Parity::kEven, 1}), "19200 8E1");
  LineSettings s;
  ASSERT_TRUE(parse_format("8o2", s));
  EXPECT_EQ(s.parity, Parity::kOdd);
  EXPECT_EQ(s.stop_bits, 2);
  for (const char* bad : {"", "8N", "9N1", "8X1", "8N3", "8N11"}) {
    EXPECT_FALSE(parse_format(bad, s)) << bad;
  }
}
