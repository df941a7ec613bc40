// Baud rates ([IEC 61158-4-3 UART character] [IEC 61158-2 baud rates]) and bit-time arithmetic
// ([IEC 61158-4-3 UART character, bus parameters, timing] [IEC 61158-2 baud rates]).
#include "dp/time/baud_rate.h"

#include <gtest/gtest.h>

namespace rs4sim::dp {
namespace {

using namespace std::chrono_literals;

TEST(BaudRate, ParsesEveryStandardRateInBothSpellings) {
  EXPECT_EQ(parse_baud_rate("9600"), BaudRate::k9k6);
  EXPECT_EQ(parse_baud_rate("9.6k"), BaudRate::k9k6);
  EXPECT_EQ(parse_baud_rate("19.2K"), BaudRate::k19k2);
  EXPECT_EQ(parse_baud_rate("45.45k"), BaudRate::k45k45);
  EXPECT_EQ(parse_baud_rate("45450"), BaudRate::k45k45);
  EXPECT_EQ(parse_baud_rate("93.75k"), BaudRate::k93k75);
  EXPECT_EQ(parse_baud_rate("187.5k"), BaudRate::k187k5);
  EXPECT_EQ(parse_baud_rate("500k"), BaudRate::k500k);
  EXPECT_EQ(parse_baud_rate("1.5M"), BaudRate::k1M5);
  EXPECT_EQ(parse_baud_rate("1500000"), BaudRate::k1M5);
  EXPECT_EQ(parse_baud_rate("3M"), BaudRate::k3M);
  EXPECT_EQ(parse_baud_rate("6m"), BaudRate::k6M);
  EXPECT_EQ(parse_baud_rate("12M"), BaudRate::k12M);
}

TEST(BaudRate, RejectsNonStandardAndMalformedText) {
  for (const char* bad : {"", "k", "115200", "31.25k", "1.5", "12MM", "-9600", "9600.0", "1.2345M",
                          "abc", "99999999999999999999", " 9600"}) {
    EXPECT_FALSE(parse_baud_rate(bad).has_value()) << bad;
  }
}

TEST(BaudRate, NamesAndList) {
  EXPECT_EQ(to_string(BaudRate::k45k45), "45.45k");
  EXPECT_EQ(to_string(BaudRate::k1M5), "1.5M");
  EXPECT_EQ(to_string(BaudRate::k12M), "12M");
  EXPECT_EQ(standard_baud_rate_list(),
            "9.6k, 19.2k, 45.45k, 93.75k, 187.5k, 500k, 1.5M, 3M, 6M, 12M");
}

TEST(BaudRate, BitTimesFromTheSpec) {
  // [IEC 61158-4-3 UART character] [IEC 61158-2 baud rates]: 1 Tbit = 83.3 ns at 12M, 667 ns
  // at 1.5M, 104.2 µs at 9.6k (rounded up to ns).
  EXPECT_EQ(bit_time(BaudRate::k12M, 1), 84ns);
  EXPECT_EQ(bit_time(BaudRate::k1M5, 1), 667ns);
  EXPECT_EQ(bit_time(BaudRate::k9k6, 1), 104'167ns);
  // TSYN (33 bit) at 12M is 2.75 µs exactly; one 11-bit character at 9.6k 1.1458 ms.
  EXPECT_EQ(bit_time(BaudRate::k12M, kTsynBits), 2750ns);
  EXPECT_EQ(bit_time(BaudRate::k9k6, telegram_bits(1)), 1'145'834ns);
  EXPECT_EQ(telegram_bits(6), 66U);  // SD1 frame, [IEC 61158-4-3 frame formats]
}

}  // namespace
}  // namespace rs4sim::dp
