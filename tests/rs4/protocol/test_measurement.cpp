// COM_CMD_MESS_16_RT 0x23 ([RS4 manual §5.2.3.4, table 5.2-14]).
#include "rs4/protocol/measurement.h"
#include "rs4/protocol/telegram.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

namespace rs4sim::rs4::protocol {
namespace {

using Bytes = std::vector<std::uint8_t>;

// The measurement of the [roboticslibrary/rl LeuzeRs4.cpp] worked example, unstuffed (the body on
// PROFIBUS).
const Bytes kExampleBody{
    0x23,        // 5: COM_CMD_MESS_16_RT
    0x0B,        // 6: option 1: 3 option bytes, state measuring
    0x80,        // 7: option 2: option 3 follows
    0x81,        // 8: option 3: field pair 1
    0x00, 0xFE,  // 9..10: scan b31..24 = 0, filler
    0x00, 0xFE,  // 11..12: scan b23..16 = 0, filler
    0x00, 0xFE,  // 13..14: scan b15..8 = 0, filler
    0x01, 0xFE,  // 15..16: scan b7..0 = 1, filler
    0x04,        // 17: resolution 4
    0x00, 0x00,  // 18..19: output start 0
    0x00, 0x08,  // 20..21: output stop 8
    0x03, 0xE8,  // 22..23: segment 0: 1000 mm
    0x00, 0x00,  // 24..25: segment 4: 0 mm
    0x01, 0x00,  // 26..27: segment 8: 256 mm
};

TEST(Rs4Measurement, DecodesWorkedExample) {
  auto d = decode_telegram(kExampleBody);
  ASSERT_TRUE(d);
  ASSERT_TRUE(std::holds_alternative<MeasurementTelegram>(d.value()));
  const auto& m = std::get<MeasurementTelegram>(d.value());
  EXPECT_EQ(m.scan_number, 1U);
  EXPECT_EQ(m.resolution, 4);
  EXPECT_EQ(m.start, 0);
  EXPECT_EQ(m.stop, 8);
  EXPECT_EQ(m.values, (std::vector<std::uint16_t>{1000, 0, 256}));
  EXPECT_EQ(m.prefix.options.first_field_pair, 1);
}

TEST(Rs4Measurement, EncodesWorkedExample) {
  MeasurementTelegram m;
  m.prefix.options.state = Option1State::kMeasuring;
  m.prefix.options.first_field_pair = 1;
  m.scan_number = 1;
  m.resolution = 4;
  m.start = 0;
  m.stop = 8;
  m.values = {1000, 0, 256};
  auto e = encode_telegram(m);
  ASSERT_TRUE(e);
  EXPECT_EQ(e.value(), kExampleBody);
}

TEST(Rs4Measurement, ScanNumberHighByteFirstWithFillers) {
  std::array<std::uint16_t, kContourSegments> contour{};
  Bytes out;
  ASSERT_FALSE(encode_measurement_data(0x12345678, 1, 0, 0, contour, out));
  const Bytes expected{0x12, 0xFE, 0x34, 0xFE, 0x56, 0xFE, 0x78, 0xFE,  // scan number
                       0x01,                                            // resolution 1
                       0x00, 0x00, 0x00, 0x00,                          // start 0, stop 0
                       0x00, 0x00};                                     // one value
  EXPECT_EQ(out, expected);
}

TEST(Rs4Measurement, ValueCountOfTheManualsExample) {
  // start 0, stop 528, resolution 4 → segments 0, 4, …, 524, 528 = 133 values
  // ([RS4 manual §5.2.3.4]).
  EXPECT_EQ(measurement_value_count(0, 528, 4).value(), 133U);
  EXPECT_EQ(measurement_value_count(0, 528, 1).value(), 529U);
  EXPECT_EQ(measurement_value_count(10, 10, 7).value(), 1U);
  // 0..10 by 4: 0, 4, 8 and the stop 10 → 4 values
  EXPECT_EQ(measurement_value_count(0, 10, 4).value(), 4U);
}

TEST(Rs4Measurement, ContourEncodingPicksSegmentsAndAlwaysTheStop) {
  std::array<std::uint16_t, kContourSegments> contour{};
  for (std::size_t i = 0; i < contour.size(); ++i) contour[i] = static_cast<std::uint16_t>(2 * i);
  Bytes out;
  ASSERT_FALSE(encode_measurement_data(0, 4, 0, 10, contour, out));
  ASSERT_EQ(out.size(), 13U + 8U);
  const Bytes values(out.begin() + 13, out.end());
  EXPECT_EQ(values, (Bytes{0x00, 0x00,     // segment 0
                           0x00, 0x08,     // segment 4: 8
                           0x00, 0x10,     // segment 8: 16
                           0x00, 0x14}));  // stop segment 10: 20
  Bytes full;
  ASSERT_FALSE(encode_measurement_data(7, 4, 0, 528, contour, full));
  EXPECT_EQ(full.size(), 13U + 2U * 133U);
  EXPECT_EQ(full[full.size() - 2], (2 * 528) >> 8);  // last value = segment 528
  EXPECT_EQ(full[full.size() - 1], (2 * 528) & 0xFF);
}

TEST(Rs4Measurement, ValueBit0IsTheProtectiveFieldFlag) {
  EXPECT_EQ(measurement_value(1001, false), 1000);  // odd distances lose bit 0
  EXPECT_EQ(measurement_value(1000, true), 1001);
  EXPECT_EQ(value_distance_mm(1001), 1000);
  EXPECT_TRUE(value_field_violated(1001));
  EXPECT_FALSE(value_field_violated(1000));
}

TEST(Rs4Measurement, WindowErrors) {
  EXPECT_EQ(measurement_value_count(0, 10, 0).error(), ProtocolError::kBadResolution);
  EXPECT_EQ(measurement_value_count(0, 529, 1).error(), ProtocolError::kSegmentOutOfRange);
  EXPECT_EQ(measurement_value_count(529, 529, 1).error(), ProtocolError::kSegmentOutOfRange);
  EXPECT_EQ(measurement_value_count(11, 10, 1).error(), ProtocolError::kStartAfterStop);
  MeasurementTelegram m;
  m.values = {1, 2, 3};  // default window 0..528 at resolution 1 needs 529
  EXPECT_EQ(encode_telegram(m).error(), ProtocolError::kValueCountMismatch);
}

TEST(Rs4Measurement, DecoderTypedErrors) {
  auto with = [](std::size_t at, std::uint8_t value) {
    Bytes b = kExampleBody;
    b[at] = value;
    return decode_telegram(b);
  };
  EXPECT_EQ(with(5, 0x00).error(), ProtocolError::kBadScanNumberFiller);  // filler not FE
  EXPECT_EQ(with(12, 0x00).error(), ProtocolError::kBadResolution);
  EXPECT_EQ(with(14, 0x09).error(), ProtocolError::kStartAfterStop);     // start 9 > stop 8
  EXPECT_EQ(with(15, 0x03).error(), ProtocolError::kSegmentOutOfRange);  // stop 0x0308 = 776
  Bytes truncated(kExampleBody.begin(), kExampleBody.end() - 1);
  EXPECT_EQ(decode_telegram(truncated).error(), ProtocolError::kTruncated);
  Bytes longer = kExampleBody;
  longer.insert(longer.end(), {0x00, 0x00});
  EXPECT_EQ(decode_telegram(longer).error(), ProtocolError::kTrailingBytes);
  Bytes header_only(kExampleBody.begin(), kExampleBody.begin() + 10);
  EXPECT_EQ(decode_telegram(header_only).error(), ProtocolError::kTruncated);
}

}  // namespace
}  // namespace rs4sim::rs4::protocol
