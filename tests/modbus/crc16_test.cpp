#include "modbus/crc16.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>

namespace rs4sim::modbus {
namespace {

TEST(Crc16, CatalogueCheckValue) {
  // CRC-16/MODBUS check value over ASCII "123456789" (the CRC catalogue's "check").
  const std::array<std::uint8_t, 9> ascii{'1', '2', '3', '4', '5', '6', '7', '8', '9'};
  EXPECT_EQ(crc16(ascii), 0x4B37);
}

TEST(Crc16, ModbusSpecReadHoldingExample) {
  // slave 01, FC 03, start 0x006B, 3 registers: CRC bytes on the wire 74 17 (low first)
  // [Modbus application protocol V1.1b3 §6.3] request, RTU framed.
  const std::array<std::uint8_t, 6> pdu{0x01, 0x03, 0x00, 0x6B, 0x00, 0x03};
  EXPECT_EQ(crc16(pdu), 0x1774);
}

TEST(Crc16, PolarisScreenshotRequest) {
  // P1 [Polaris manual §7.4]: 03 03 20 00 00 08 | 4E 2E
  const std::array<std::uint8_t, 6> pdu{0x03, 0x03, 0x20, 0x00, 0x00, 0x08};
  EXPECT_EQ(crc16(pdu), 0x2E4E);
}

TEST(Crc16, EmptyIsInit) { EXPECT_EQ(crc16({}), 0xFFFF); }

}  // namespace
}  // namespace rs4sim::modbus
