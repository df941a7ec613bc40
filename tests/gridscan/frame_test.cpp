// The CEDES frame codec against every frame of [GridScan manual §10.3] and the frames the
// project computed with the manual's layout (docs/gridscan.md "Known answers"), as
// annotated bytes.
#include "gridscan/frame.h"

#include "gridscan/crc32_mpeg2.h"
#include "gridscan/payload.h"

#include <gtest/gtest.h>

#include <string_view>
#include <vector>

namespace rs4sim::gridscan {
namespace {

using Bytes = std::vector<std::uint8_t>;

std::span<const std::uint8_t> ascii(std::string_view s) {
  return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

TEST(GridScanCrc, CatalogueCheckValue) {
  EXPECT_EQ(crc32_mpeg2(ascii("123456789")), 0x0376E6E7U);  // CRC-32/MPEG-2 check
  const Bytes seq_id{0x06, 0x23};
  EXPECT_EQ(crc32_mpeg2(seq_id), 0x70014BE2U);  // [GridScan manual §10.3] request 4
}

struct Known {
  const char* what;
  Frame frame;
  Bytes wire;
};

std::vector<Known> requests() {
  return {
      {"communication test, SeqCnt 6 ([GridScan manual §10.3] request 4)",
       {0x06, 0x23, {}},
       {0x43, 0x45, 0x44, 0x45,    // sync "CEDE"
        0x06,                      // SeqCnt
        0x23,                      // ID: Info: Communication test, direction 0
        0xE2, 0x4B, 0x01, 0x70}},  // CRC-32 0x70014BE2, LSB first
      {"Set polling",
       {0x02, 0x10, {}},
       {0x43, 0x45, 0x44, 0x45, 0x02, 0x10, 0x02, 0x21, 0x54, 0xEC}},
      {"Set stand-by",
       {0x02, 0x13, {}},
       {0x43, 0x45, 0x44, 0x45, 0x02, 0x13, 0xDB, 0x07, 0x17, 0xE1}},
      {"Reduced state",
       {0x02, 0x30, {}},
       {0x43, 0x45, 0x44, 0x45, 0x02, 0x30, 0xE2, 0x97, 0x77, 0x74}},
      {"Full state",
       {0x02, 0x31, {}},
       {0x43, 0x45, 0x44, 0x45, 0x02, 0x31, 0x55, 0x8A, 0xB6, 0x70}},
      {"Test input",
       {0x02, 0x40, {}},
       {0x43, 0x45, 0x44, 0x45, 0x02, 0x40, 0x05, 0x8A, 0xC3, 0x94}},
      {"Allow change",
       {0x02, 0x50, {}},
       {0x43, 0x45, 0x44, 0x45, 0x02, 0x50, 0x75, 0x51, 0xD2, 0xD8}},
      {"Set static",
       {0x02, 0x51, {}},
       {0x43, 0x45, 0x44, 0x45, 0x02, 0x51, 0xC2, 0x4C, 0x13, 0xDC}},
      {"Config get current",
       {0x02, 0x53, {}},
       {0x43, 0x45, 0x44, 0x45, 0x02, 0x53, 0xAC, 0x77, 0x91, 0xD5}},
      // The correct CRCs of [GridScan manual §10.3] requests 1..3 (which carry 00 00 00 00).
      {"comm test SeqCnt 0",
       {0x00, 0x23, {}},
       {0x43, 0x45, 0x44, 0x45, 0x00, 0x23, 0x44, 0xF4, 0xD7, 0x95}},
      {"comm test SeqCnt 2",
       {0x02, 0x23, {}},
       {0x43, 0x45, 0x44, 0x45, 0x02, 0x23, 0x4B, 0x6A, 0x25, 0x35}},
      {"comm test SeqCnt 4",
       {0x04, 0x23, {}},
       {0x43, 0x45, 0x44, 0x45, 0x04, 0x23, 0xED, 0xD5, 0xF3, 0xD0}},
  };
}

std::vector<Known> responses() {
  return {
      {"[GridScan manual §10.3] answer 1: sync, SeqCnt and CRC wrong",
       {0x01, 0xA3, {0x07}},
       {0x43, 0x45, 0x44, 0x45,    // sync
        0x01,                      // SeqCnt = request 0 + 1
        0xA3,                      // 0x23 | direction bit
        0x07,                      // b0 CRC, b1 SeqCnt, b2 sync wrong
        0xEF, 0x30, 0x3F, 0x78}},  // CRC LSB first
      {"answer 2: SeqCnt OK",
       {0x03, 0xA3, {0x05}},
       {0x43, 0x45, 0x44, 0x45, 0x03, 0xA3, 0x05, 0x8F, 0x52, 0x0C, 0x72}},
      {"answer 3: sync OK",
       {0x05, 0xA3, {0x01}},
       {0x43, 0x45, 0x44, 0x45, 0x05, 0xA3, 0x01, 0x41, 0xCF, 0xDB, 0x65}},
      {"answer 4: all correct",
       {0x07, 0xA3, {0x00}},
       {0x43, 0x45, 0x44, 0x45, 0x07, 0xA3, 0x00, 0xF8, 0x8B, 0xAB, 0x62}},
      {"empty answer to Set polling",
       {0x03, 0x90, {}},
       {0x43, 0x45, 0x44, 0x45, 0x03, 0x90, 0x30, 0x00, 0x41, 0x57}},
      {"Reduced state: door 22 open, clear, clean",
       {0x03, 0xB0, {0x16, 0x00}},
       {0x43, 0x45, 0x44, 0x45, 0x03, 0xB0,
        0x16,                      // door position 22 = open
        0x00,                      // b8 clear, b9 no failure, maintenance 0
        0xB0, 0x50, 0x3D, 0x98}},  // CRC
      {"Reduced state: interrupted",
       {0x03, 0xB0, {0x16, 0x01}},
       {0x43, 0x45, 0x44, 0x45, 0x03, 0xB0, 0x16, 0x01, 0x07, 0x4D, 0xFC, 0x9C}},
      {"Reduced state: static (door 255)",
       {0x03, 0xB0, {0xFF, 0x00}},
       {0x43, 0x45, 0x44, 0x45, 0x03, 0xB0, 0xFF, 0x00, 0xCC, 0x50, 0x05, 0x23}},
      {"Full state: 22 elements, 1 and 22 interrupted, light soiling",
       {0x03, 0xB1, {0x16, 0x41, 0x01, 0x00, 0x20}},
       {0x43, 0x45, 0x44, 0x45, 0x03, 0xB1,
        0x16,                      // door open
        0x41,                      // b8 interrupted, b14..15 = 1 light soiling
        0x01, 0x00, 0x20,          // element 1 (bit 16), element 22 (bit 37)
        0x20, 0x57, 0xA4, 0x95}},  // CRC
      {"power-up version: SW 01.02, HW 03.04",
       {0x00, 0xA0, {0x30, 0x31, 0x2E, 0x30, 0x32, 0x30, 0x33, 0x2E, 0x30, 0x34}},
       {0x43, 0x45, 0x44, 0x45, 0x00, 0xA0,
        0x30, 0x31, 0x2E, 0x30, 0x32,  // SW "01.02", first character first
        0x30, 0x33, 0x2E, 0x30, 0x34,  // HW "03.04"
        0x33, 0x7F, 0x67, 0x4B}},      // CRC
      {"Config get current: static",
       {0x09, 0xD3, {0x55}},
       {0x43, 0x45, 0x44, 0x45, 0x09, 0xD3, 0x55, 0xC7, 0x05, 0x5B, 0x76}},
  };
}

TEST(GridScanFrame, EncodesEveryKnownRequest) {
  for (const auto& k : requests()) EXPECT_EQ(encode(k.frame), k.wire) << k.what;
}

TEST(GridScanFrame, DecodesEveryKnownRequest) {
  for (const auto& k : requests()) {
    auto f = decode_request(k.wire);
    ASSERT_TRUE(f) << k.what << ": " << f.error().message();
    EXPECT_EQ(f.value(), k.frame) << k.what;
  }
}

TEST(GridScanFrame, EncodesAndDecodesEveryKnownResponse) {
  for (const auto& k : responses()) {
    EXPECT_EQ(encode(k.frame), k.wire) << k.what;
    auto f = decode_response(k.wire, 22);
    ASSERT_TRUE(f) << k.what << ": " << f.error().message();
    EXPECT_EQ(f.value(), k.frame) << k.what;
  }
}

TEST(GridScanFrame, InspectReportsSyncAndCrcOfTheManualsBadRequests) {
  const Bytes request1{0x00, 0x00, 0x00, 0x00, 0x00, 0x23, 0x00, 0x00, 0x00, 0x00};
  auto raw = inspect(request1);
  ASSERT_TRUE(raw);
  EXPECT_FALSE(raw.value().sync_ok);
  EXPECT_FALSE(raw.value().crc_ok());
  EXPECT_EQ(raw.value().crc_computed, 0x95D7F444U);  // 44 F4 D7 95 on the wire
  EXPECT_EQ(decode_request(request1).error(), FrameError::kBadSync);
  const Bytes request3{0x43, 0x45, 0x44, 0x45, 0x04, 0x23, 0x00, 0x00, 0x00, 0x00};
  EXPECT_EQ(decode_request(request3).error(), FrameError::kBadCrc);
}

TEST(GridScanFrame, RejectsBadShapes) {
  Bytes ok{0x43, 0x45, 0x44, 0x45, 0x06, 0x23, 0xE2, 0x4B, 0x01, 0x70};
  EXPECT_EQ(inspect(std::span(ok).first(9)).error(), FrameError::kTooShort);
  Bytes long21(21, 0x00);
  EXPECT_EQ(inspect(long21).error(), FrameError::kTooLong);
  EXPECT_EQ(decode_request(encode({0x06, 0xA3, {}})).error(), FrameError::kDirectionBit);
  EXPECT_EQ(decode_request(encode({0x06, 0x26, {}})).error(), FrameError::kUnknownId);
  EXPECT_EQ(decode_request(encode({0x06, 0x23, {0x00}})).error(), FrameError::kRequestPayload);
  EXPECT_EQ(decode_response(encode({0x06, 0x23, {0x00}}), 22).error(), FrameError::kDirectionBit);
  EXPECT_EQ(decode_response(encode({0x06, 0xB1, {0x16, 0x00}}), 22).error(),
            FrameError::kPayloadLength);
  EXPECT_EQ(make_error_code(FrameError::kBadCrc).category().name(), std::string("gridscan.frame"));
  EXPECT_EQ(make_error_code(FrameError::kBadCrc).message(), "CRC-32 mismatch");
}

TEST(GridScanFrame, FullStatePayloadSizeFollowsTheElementCount) {
  EXPECT_EQ(response_payload_size(CommandId::kDataFullState, 12), 4U);
  EXPECT_EQ(response_payload_size(CommandId::kDataFullState, 22), 5U);
  EXPECT_EQ(response_payload_size(CommandId::kDataFullState, 60), 10U);
  EXPECT_EQ(response_payload_size(CommandId::kModeSetPolling, 60), 0U);
}

}  // namespace
}  // namespace rs4sim::gridscan
