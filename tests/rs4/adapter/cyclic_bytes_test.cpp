// Cyclic process bytes and address switches ([RS4 manual §4.5, §5.1],
// [RS4 manual §5.1.1, §5.1.2]). Known answers written from the manual's tables.
#include "rs4/adapter/cyclic_bytes.h"

#include "rs4/adapter/rs4_gsd.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <utility>

namespace rs4sim::rs4::adapter {
namespace {

TEST(InputByte, EachBitFromTheSpecTable) {
  // [RS4 manual §5.1.1]: bit 7 OSSD, 6 warning output inverted, 5 error, 4 operating state,
  //       3 RS232 active, 2 Proxy-Request, 1 protective field, 0 warning field.
  InputBits b;  // warning output not active → bit 6 = 1
  EXPECT_EQ(encode_input_byte(b), 0x40);
  b.warning_output_active = true;  // inverted: active → 0
  EXPECT_EQ(encode_input_byte(b), 0x00);
  b.ossd = true;
  EXPECT_EQ(encode_input_byte(b), 0x80);
  // Each other bit alone, over the warning output's 1 in bit 6.
  const std::pair<bool InputBits::*, std::uint8_t> alone[] = {
      {&InputBits::error, 0x60},
      {&InputBits::not_operational, 0x50},
      {&InputBits::rs232_active, 0x48},
      {&InputBits::proxy_request, 0x44},
      {&InputBits::protective_field, 0x42},
      {&InputBits::warning_field, 0x41},
  };
  for (const auto& [bit, byte] : alone) {
    b = {};
    b.*bit = true;
    EXPECT_EQ(encode_input_byte(b), byte) << int{byte};
  }
}

TEST(InputByte, DecodeFixedBytes) {
  // 0xC4 = 1100 0100:
  //   bit 7 = 1 OSSD on
  //   bit 6 = 1 warning output NOT set (inverted)
  //   bit 2 = 1 Proxy-Request
  const auto b = decode_input_byte(0xC4);
  EXPECT_TRUE(b.ossd);
  EXPECT_FALSE(b.warning_output_active);
  EXPECT_TRUE(b.proxy_request);
  EXPECT_FALSE(b.error || b.not_operational || b.rs232_active || b.protective_field ||
               b.warning_field);
  for (unsigned v = 0; v < 256; ++v) {
    EXPECT_EQ(encode_input_byte(decode_input_byte(static_cast<std::uint8_t>(v))), v);
  }
}

TEST(OutputByte, DecodeFixedBytes) {
  // 0xC3 = 1100 0011: bit 7 restart, bit 6 Proxy-Enable, bits 2..0 = 011 field pair 3
  auto o = decode_output_byte(0xC3);
  EXPECT_TRUE(o.restart);
  EXPECT_TRUE(o.proxy_enable);
  EXPECT_EQ(o.field_pair, 3);
  EXPECT_TRUE(o.field_pair_valid());
  // 0x04 = field pair 4 (100), 0x05 = 101 invalid, 0x00 invalid, 0x07 invalid
  EXPECT_TRUE(decode_output_byte(0x04).field_pair_valid());
  EXPECT_FALSE(decode_output_byte(0x05).field_pair_valid());
  EXPECT_FALSE(decode_output_byte(0x00).field_pair_valid());
  EXPECT_FALSE(decode_output_byte(0x07).field_pair_valid());
  // 0x39: reserved bits 5..3 = 111 are carried but not a field pair
  o = decode_output_byte(0x39);
  EXPECT_EQ(o.reserved, 7);
  EXPECT_EQ(o.field_pair, 1);
  for (unsigned v = 0; v < 256; ++v) {
    EXPECT_EQ(encode_output_byte(decode_output_byte(static_cast<std::uint8_t>(v))), v);
  }
}

TEST(AddressSwitches, FactorySettingIs4AndFDestAdd504) {
  const AddressSwitches factory{};
  ASSERT_TRUE(station_address(factory));
  EXPECT_EQ(station_address(factory).value(), 4);
  EXPECT_EQ(f_dest_add(4), 504);
  EXPECT_EQ(f_dest_add(104), 604);  // manual dialog: F_Dest_Add 604
}

TEST(AddressSwitches, Bit7IsNotEvaluated) {
  // HexH = 0x8, HexL = 0x5 → 0x85 → bit 7 masked → 5
  EXPECT_EQ(station_address({0x8, 0x5}).value(), 5);
  EXPECT_EQ(station_address({0xF, 0xE}).value(), 126);  // 0xFE → 0x7E
  EXPECT_EQ(station_address({0x7, 0xE}).value(), 126);
  EXPECT_EQ(station_address({0x0, 0x0}).value(), 0);
}

TEST(AddressSwitches, Reserved127And255AndBadNibbles) {
  EXPECT_EQ(station_address({0x7, 0xF}).error(), AddressError::kReservedAddress);  // 127
  EXPECT_EQ(station_address({0xF, 0xF}).error(), AddressError::kReservedAddress);  // 255
  EXPECT_EQ(station_address({0x10, 0x0}).error(), AddressError::kNibbleOutOfRange);
  EXPECT_EQ(station_address({0x0, 0x10}).error(), AddressError::kNibbleOutOfRange);
  EXPECT_NE(make_error_code(AddressError::kReservedAddress).message().find("127"),
            std::string::npos);
}

}  // namespace
}  // namespace rs4sim::rs4::adapter
