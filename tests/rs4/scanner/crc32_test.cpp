#include "rs4/scanner/crc32.h"

#include <gtest/gtest.h>

#include <string_view>
#include <vector>

namespace rs4sim::rs4::scanner {
namespace {

std::vector<std::uint8_t> bytes(std::string_view s) { return {s.begin(), s.end()}; }

// Published check value of CRC-32/ISO-HDLC (the CRC catalogue's "check" over "123456789").
TEST(ScannerCrc32, CheckValue) { EXPECT_EQ(crc32_iso_hdlc(bytes("123456789")), 0xCBF43926U); }

// Empty input: init 0xFFFFFFFF xor xorout 0xFFFFFFFF = 0.
TEST(ScannerCrc32, EmptyIsZero) { EXPECT_EQ(crc32_iso_hdlc({}), 0x00000000U); }

// "The quick brown fox jumps over the lazy dog" = 0x414FA339 (widely published zlib value).
TEST(ScannerCrc32, QuickBrownFox) {
  EXPECT_EQ(crc32_iso_hdlc(bytes("The quick brown fox jumps over the lazy dog")), 0x414FA339U);
}

}  // namespace
}  // namespace rs4sim::rs4::scanner
