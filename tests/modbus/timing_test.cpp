#include "modbus/timing.h"

#include <gtest/gtest.h>

#include <chrono>

namespace rs4sim::modbus {
namespace {

using std::chrono::microseconds;
using std::chrono::nanoseconds;

TEST(Timing, At19200EightN1IsCharacterTimes) {
  const stream::LineSettings s{19200, 8, stream::Parity::kNone, 1};
  // 10 bits per character at 19200 baud = 520.833 µs; 3.5 chars = 1822.917 µs.
  EXPECT_EQ(t3_5(s), nanoseconds(1822917));
  EXPECT_EQ(t1_5(s), nanoseconds(781250));
}

TEST(Timing, AboveNineteenTwoHundredIsFixed) {
  // [Modbus serial line V1.02 §2.5.1.1]: 750 µs and 1750 µs above 19200 baud.
  for (const std::uint32_t baud : {38400U, 57600U, 115200U}) {
    const stream::LineSettings s{baud, 8, stream::Parity::kNone, 1};
    EXPECT_EQ(t1_5(s), microseconds(750));
    EXPECT_EQ(t3_5(s), microseconds(1750));
  }
}

TEST(Timing, SlowLinesScale) {
  const stream::LineSettings s{9600, 8, stream::Parity::kEven, 1};  // 11 bits
  EXPECT_EQ(t3_5(s), nanoseconds(4010417));
}

}  // namespace
}  // namespace rs4sim::modbus
