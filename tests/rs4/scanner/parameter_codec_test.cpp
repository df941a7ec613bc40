// Parameter-set encoding (EXTENSION): the expected bytes are written by hand from the
// layout table in docs/rs4-scanner.md "Encoding", not produced by the encoder.
#include "rs4/scanner/parameter_codec.h"

#include "rs4/scanner/crc32.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <vector>

namespace rs4sim::rs4::scanner {
namespace {

ParameterSet sample() {
  ParameterSet s = factory_default();
  s.identity = Identity{0x0A0B0C0D, 0x0004, 2, 7};
  s.response_steps = 3;
  s.restart_mode = RestartMode::kStartInterlock;
  s.start_pair = 2;
  s.permitted = {0x03, 0x0F, 0x04, 0x09};
  s.warning_output = kWarnOnContamination | kWarnOnWarningField;
  s.measurement = {4, 0, 528};
  s.passwords[0] = {'R', 'O', 'D', '4', 'L', 'E', 0xFF, 0xFF};
  s.passwords[1].fill(0xFF);
  s.pairs[0].protective_mm[0] = 0x0102;
  s.pairs[0].warning_mm[528] = 0x3A98;  // 15000 mm
  s.pairs[3].warning_mm[528] = 0x0DAC;  // 3500 mm (factory)
  return s;
}

const std::vector<std::uint8_t> kHeader = {
    0x52, 0x53, 0x34, 0x50,  // 0..3   magic "RS4P"
    0x01,                    // 4      format version 1
    0x00,                    // 5      reserved
    0x0A, 0x0B, 0x0C, 0x0D,  // 6..9   serial number 0x0A0B0C0D, big-endian
    0x00, 0x04,              // 10..11 device type 0x0004
    0x02,                    // 12     firmware major 2
    0x07,                    // 13     firmware minor 7
    0x03,                    // 14     response steps n = 3 (T = 200 ms)
    0x01,                    // 15     restart mode 1 = start interlock
    0x02,                    // 16     start pair 2
    0x03,                    // 17     permitted from pair 1: to 1, 2
    0x0F,                    // 18     permitted from pair 2: to 1..4
    0x04,                    // 19     permitted from pair 3: to 3
    0x09,                    // 20     permitted from pair 4: to 1, 4
    0x03,                    // 21     warning output: contamination | warning field
    0x04,                    // 22     measurement resolution 4
    0x00, 0x00,              // 23..24 measurement start 0
    0x02, 0x10,              // 25..26 measurement stop 528
    'R',  'O',  'D',  '4',  'L',  'E',  0xFF, 0xFF,  // 27..34 password 1
    0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF,  // 35..42 password 2 (none)
};

TEST(ScannerParameterCodec, SizeFromLayout) {
  EXPECT_EQ(kParameterSetSize, 43U + 4U * 2U * 529U * 2U);  // 8507
  EXPECT_EQ(encode(sample()).size(), kParameterSetSize);
}

TEST(ScannerParameterCodec, HeaderBytes) {
  const auto bytes = encode(sample());
  ASSERT_GE(bytes.size(), kHeader.size());
  EXPECT_TRUE(std::equal(kHeader.begin(), kHeader.end(), bytes.begin()));
}

// The big-endian 16-bit value of bytes `offset` and `offset` + 1.
unsigned u16_be_at(const std::vector<std::uint8_t>& b, std::size_t offset) {
  return (unsigned{b.at(offset)} << 8U) | unsigned{b.at(offset + 1)};
}

TEST(ScannerParameterCodec, FieldPairBytes) {
  const auto b = encode(sample());
  // pair 1 protective segment 0 at offset 43: 0x0102 big-endian
  EXPECT_EQ(u16_be_at(b, 43), 0x0102U);
  // pair 1 protective segment 1 at 45: factory 1000 mm = 0x03E8
  EXPECT_EQ(u16_be_at(b, 45), 0x03E8U);
  // pair 1 warning segment 0 at 43 + 1058 = 1101: factory 2000 mm = 0x07D0
  EXPECT_EQ(u16_be_at(b, 1101), 0x07D0U);
  // pair 1 warning segment 528 at 1101 + 1056 = 2157: 0x3A98
  EXPECT_EQ(u16_be_at(b, 2157), 0x3A98U);
  // pair 2 protective segment 0 at 43 + 2116 = 2159: factory 1500 mm = 0x05DC
  EXPECT_EQ(u16_be_at(b, 2159), 0x05DCU);
  // last two bytes: pair 4 warning segment 528 = 0x0DAC
  EXPECT_EQ(u16_be_at(b, 8505), 0x0DACU);
}

TEST(ScannerParameterCodec, DecodeFixedBytes) {
  std::vector<std::uint8_t> b = kHeader;
  for (int p = 0; p < 4; ++p) {
    for (int n = 0; n < 2 * 529; ++n) {  // every value 0x0100 + pair = (p+1)*256 + ...
      b.push_back(static_cast<std::uint8_t>(p + 1));
      b.push_back(static_cast<std::uint8_t>(n & 0x7F));
    }
  }
  const auto r = decode(b);
  ASSERT_TRUE(r) << r.error().message();
  const ParameterSet& s = r.value();
  EXPECT_EQ(s.identity.serial_number, 0x0A0B0C0DU);
  EXPECT_EQ(s.identity.firmware_minor, 7);
  EXPECT_EQ(s.response_steps, 3);
  EXPECT_EQ(s.restart_mode, RestartMode::kStartInterlock);
  EXPECT_EQ(s.start_pair, 2);
  EXPECT_EQ(s.permitted[3], 0x09);
  EXPECT_EQ(s.measurement.stop, 528);
  EXPECT_EQ(s.passwords[0][3], '4');
  EXPECT_EQ(s.pairs[0].protective_mm[1], 0x0101);
  EXPECT_EQ(s.pairs[0].warning_mm[0], 0x0100 | (529 & 0x7F));  // n = 529 → warning seg 0
  EXPECT_EQ(s.pairs[3].protective_mm[5], 0x0405);
}

TEST(ScannerParameterCodec, RoundTrip) {
  const ParameterSet s = sample();
  const auto r = decode_and_validate(encode(s));
  ASSERT_TRUE(r) << r.error().message();
  EXPECT_EQ(r.value(), s);
}

TEST(ScannerParameterCodec, ChecksumIsCrcOfEncoding) {
  const ParameterSet s = sample();
  const auto bytes = encode(s);
  EXPECT_EQ(checksum(s), crc32_iso_hdlc(bytes));
  ParameterSet t = s;
  t.pairs[2].protective_mm[300] = 999;
  EXPECT_NE(checksum(t), checksum(s));
}

TEST(ScannerParameterCodec, SyntaxErrors) {
  const auto good = encode(sample());
  EXPECT_EQ(decode(std::span(good).first(good.size() - 1)).error(), CodecError::kTooShort);
  EXPECT_EQ(decode({}).error(), CodecError::kTooShort);
  auto longer = good;
  longer.push_back(0);
  EXPECT_EQ(decode(longer).error(), CodecError::kTooLong);
  auto magic = good;
  magic[3] = 'Q';
  EXPECT_EQ(decode(magic).error(), CodecError::kBadMagic);
  auto version = good;
  version[4] = 0x02;
  EXPECT_EQ(decode(version).error(), CodecError::kUnsupportedVersion);
  auto reserved = good;
  reserved[5] = 0x01;
  EXPECT_EQ(decode(reserved).error(), CodecError::kReservedNotZero);
}

TEST(ScannerParameterCodec, SemanticErrorAfterSyntax) {
  auto b = encode(sample());
  b[16] = 0x05;            // start pair 5
  EXPECT_TRUE(decode(b));  // syntax fine
  EXPECT_EQ(decode_and_validate(b).error(), ParameterError::kStartPair);
  b[16] = 0x02;
  b[43] = 0x0F;  // pair 1 protective seg 0 = 0x0FA1
  b[44] = 0xA1;  // = 4001 mm
  EXPECT_EQ(decode_and_validate(b).error(), ParameterError::kProtectiveTooFar);
}

std::vector<std::uint8_t> read_seed(const char* name) {
  std::ifstream in(std::string(RS4SIM_SCANNER_CORPUS) + "/" + name, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The factory-default seed was generated from the documented layout by a separate script.
TEST(ScannerParameterCodec, FactoryDefaultMatchesDocumentedBytes) {
  const auto seed = read_seed("factory_default");
  ASSERT_EQ(seed.size(), kParameterSetSize);
  EXPECT_EQ(encode(factory_default()), seed);
  const auto bad = read_seed("bad_start_pair");
  EXPECT_EQ(decode_and_validate(bad).error(), ParameterError::kStartPair);
  EXPECT_EQ(decode(read_seed("header_only")).error(), CodecError::kTooShort);
}

}  // namespace
}  // namespace rs4sim::rs4::scanner
