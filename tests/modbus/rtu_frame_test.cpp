#include "modbus/rtu_frame.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace rs4sim::modbus {
namespace {

using Bytes = std::vector<std::uint8_t>;

TEST(RtuFrame, DecodesModbusSpecRequest) {
  const Bytes wire{0x01,         // slave address
                   0x03,         // FC 03 read holding registers
                   0x00, 0x6B,   // start 0x006B
                   0x00, 0x03,   // 3 registers
                   0x74, 0x17};  // CRC 0x1774, low byte first
  RtuFrame f;
  ASSERT_FALSE(decode(wire, f));
  EXPECT_EQ(f.address, 0x01);
  EXPECT_EQ(f.function, 0x03);
  EXPECT_EQ(f.data, (Bytes{0x00, 0x6B, 0x00, 0x03}));
  EXPECT_EQ(encode(f), wire);
}

TEST(RtuFrame, EncodesPolarisExceptionP8) {
  // P8: slave 3, FC 3 | 0x80, code 07 (negative acknowledge), CRC A1 32.
  EXPECT_EQ(encode(RtuFrame{0x03, 0x83, {0x07}}), (Bytes{0x03, 0x83, 0x07, 0xA1, 0x32}));
}

TEST(RtuFrame, RejectsBadCrcWithoutTouchingOutput) {
  const Bytes wire{0x01, 0x03, 0x00, 0x6B, 0x00, 0x03, 0x17, 0x74};  // CRC bytes swapped
  RtuFrame f{9, 9, {1}};
  EXPECT_EQ(decode(wire, f), ModbusError::kBadCrc);
  EXPECT_EQ(f, (RtuFrame{9, 9, {1}}));
}

TEST(RtuFrame, SizeLimits) {
  RtuFrame f;
  EXPECT_EQ(decode(Bytes{0x01, 0x03, 0x00}, f), ModbusError::kTooShort);
  EXPECT_EQ(decode(Bytes(257, 0x00), f), ModbusError::kTooLong);
  // The smallest legal frame: address, function, CRC (FF FF init over 2 bytes).
  const Bytes minimal = encode(RtuFrame{0x05, 0x11, {}});
  ASSERT_EQ(minimal.size(), kMinFrameSize);
  EXPECT_FALSE(decode(minimal, f));
  const Bytes maximal = encode(RtuFrame{0x05, 0x10, Bytes(252, 0xA5)});
  ASSERT_EQ(maximal.size(), kMaxFrameSize);
  EXPECT_FALSE(decode(maximal, f));
  EXPECT_EQ(f.data.size(), 252U);
}

TEST(RtuFrame, ErrorsHaveTheModbusCategory) {
  const std::error_code ec = ModbusError::kBadCrc;
  EXPECT_STREQ(ec.category().name(), "modbus");
  EXPECT_EQ(ec.message(), "RTU frame CRC mismatch");
}

}  // namespace
}  // namespace rs4sim::modbus
