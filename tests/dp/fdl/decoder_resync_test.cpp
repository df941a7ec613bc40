// Streaming decoder: one test per malformed class of [IEC 61158-4-3 frame reception], each
// followed by a good telegram that must survive the resynchronisation.
#include "collect_sink.h"

#include <gtest/gtest.h>

namespace rs4sim::dp::fdl {
namespace {

using testing::Bytes;
using testing::CollectSink;
using testing::concat;

// [docs/references.md#dp-worked-example] Slave_Diag request (FCS verified) and Data_Exchange
// request.
const Bytes kDiagReq = {0x68, 0x05, 0x05, 0x68, 0x85, 0x82, 0x6D, 0x3C, 0x3E, 0xEE, 0x16};
const Bytes kDx = {0x68, 0x04, 0x04, 0x68, 0x05, 0x02, 0x7D, 0xA5, 0x29, 0x16};

struct Outcome {
  CollectSink sink;
  DecoderStats stats;
};

Outcome run(const Bytes& stream) {
  Decoder d;
  Outcome o;
  d.feed(stream, o.sink);
  o.stats = d.stats();
  return o;
}

void feed(Decoder& d, CollectSink& sink, const Bytes& stream, bool byte_by_byte) {
  if (byte_by_byte) {
    for (const std::uint8_t b : stream) d.feed(std::span<const std::uint8_t>(&b, 1), sink);
  } else {
    d.feed(stream, sink);
  }
}

// `bad` followed by both good frames: first error is `e`, both good frames arrive in order.
void expect_resync(const Bytes& bad, DecodeError e) {
  for (const bool byte_by_byte : {false, true}) {
    SCOPED_TRACE(byte_by_byte ? "byte by byte" : "one chunk");
    const Bytes stream = concat({bad, kDiagReq, kDx});
    Decoder d;
    CollectSink sink;
    feed(d, sink, stream, byte_by_byte);
    ASSERT_FALSE(sink.errors().empty());
    EXPECT_EQ(sink.errors().front(), e) << sink.errors().front().message();
    EXPECT_GE(d.stats().count(e), 1U);
    const auto ts = sink.telegrams();
    ASSERT_EQ(ts.size(), 2U);
    Bytes a;
    Bytes b;
    encode(ts[0], a);
    encode(ts[1], b);
    EXPECT_EQ(a, kDiagReq);
    EXPECT_EQ(b, kDx);
  }
}

TEST(FdlDecoderResync, GarbageBetweenFramesIsOneError) {
  const Outcome o = run(concat({{0x00, 0xFF, 0x12, 0x34}, kDiagReq, {0x01, 0x02}, kDx}));
  EXPECT_EQ(o.sink.telegrams().size(), 2U);
  EXPECT_EQ(o.stats.count(DecodeError::kGarbage), 2U);  // one per run of garbage
  EXPECT_EQ(o.stats.discarded_bytes, 6U);
  expect_resync({0x00, 0xFF, 0x12, 0x34}, DecodeError::kGarbage);
}

TEST(FdlDecoderResync, BadFcsDropsTheWholeFrame) {
  // DX with FCS 0x2A instead of 0x29.
  expect_resync({0x68, 0x04, 0x04, 0x68, 0x05, 0x02, 0x7D, 0xA5, 0x2A, 0x16}, DecodeError::kBadFcs);
  // A data byte E5 inside a frame with a bad FCS must not become a short ack: ED confirms
  // the framing, so the frame is dropped as a whole.
  const Outcome o =
      run(concat({{0x68, 0x04, 0x04, 0x68, 0x05, 0x02, 0x7D, 0xE5, 0x00, 0x16}, kDx}));
  ASSERT_EQ(o.sink.events.size(), 2U);
  EXPECT_EQ(o.sink.errors().at(0), DecodeError::kBadFcs);
  EXPECT_EQ(o.sink.telegrams().at(0).type, FrameType::kSd2);
  EXPECT_EQ(o.stats.discarded_bytes, 10U);
  // SD1 and SD3 with a bad FCS.
  expect_resync({0x10, 0x05, 0x02, 0x49, 0x51, 0x16}, DecodeError::kBadFcs);
  expect_resync(
      {0xA2, 0x82, 0x85, 0x08, 0x3E, 0x3C, 0x02, 0x05, 0x00, 0xFF, 0x12, 0x34, 0xD6, 0x16},
      DecodeError::kBadFcs);
}

TEST(FdlDecoderResync, BadEndDelimiter) {
  expect_resync({0x68, 0x04, 0x04, 0x68, 0x05, 0x02, 0x7D, 0xA5, 0x29, 0x17},
                DecodeError::kBadEndDelimiter);
  expect_resync({0x10, 0x05, 0x02, 0x49, 0x50, 0x00}, DecodeError::kBadEndDelimiter);
}

TEST(FdlDecoderResync, LostTailDoesNotSwallowTheNextFrame) {
  // A diag reply cut after 11 of its 17 bytes: its nominal end lies inside the next frame.
  expect_resync({0x68, 0x0B, 0x0B, 0x68, 0x82, 0x85, 0x08, 0x3E, 0x3C, 0x02, 0x05},
                DecodeError::kBadEndDelimiter);
}

TEST(FdlDecoderResync, LengthMismatch) {
  expect_resync({0x68, 0x05, 0x06, 0x68, 0x85, 0x82, 0x6D, 0x3C, 0x3E, 0xEE, 0x16},
                DecodeError::kLengthMismatch);
}

TEST(FdlDecoderResync, LengthOutOfRange) {
  expect_resync({0x68, 0x02, 0x02, 0x68, 0x05, 0x02, 0x07, 0x16}, DecodeError::kLengthOutOfRange);
  expect_resync({0x68, 0xFA, 0xFA, 0x68}, DecodeError::kLengthOutOfRange);  // 250 > 249
}

TEST(FdlDecoderResync, RepeatedStartDelimiterMismatch) {
  expect_resync({0x68, 0x05, 0x05, 0x69, 0x85, 0x82, 0x6D, 0x3C, 0x3E, 0xEE, 0x16},
                DecodeError::kStartDelimiterMismatch);
}

TEST(FdlDecoderResync, DsapWithoutSsapAndViceVersa) {
  // DA 5|0x80, SA 2 (no ext), FC 6D, DSAP 3C, data 01, FCS 31.
  expect_resync({0x68, 0x05, 0x05, 0x68, 0x85, 0x02, 0x6D, 0x3C, 0x01, 0x31, 0x16},
                DecodeError::kSapWithoutPartner);
  // DA 5, SA 2|0x80, FC 6D, SSAP 3E, data 01, FCS 33.
  expect_resync({0x68, 0x05, 0x05, 0x68, 0x05, 0x82, 0x6D, 0x3E, 0x01, 0x33, 0x16},
                DecodeError::kSapWithoutPartner);
}

TEST(FdlDecoderResync, UnsupportedOrMissingAddressExtension) {
  // DSAP byte 7C has bit 6 set (segment address): not DP ([IEC 61158-4-3 addresses, SAPs]). FCS 2E.
  expect_resync({0x68, 0x05, 0x05, 0x68, 0x85, 0x82, 0x6D, 0x7C, 0x3E, 0x2E, 0x16},
                DecodeError::kBadAddressExtension);
  // SSAP byte BE has bit 7 set (another extension byte follows). FCS 6E.
  expect_resync({0x68, 0x05, 0x05, 0x68, 0x85, 0x82, 0x6D, 0x3C, 0xBE, 0x6E, 0x16},
                DecodeError::kBadAddressExtension);
  // SD1 cannot carry extension bytes: DA 85. FCS D0.
  expect_resync({0x10, 0x85, 0x02, 0x49, 0xD0, 0x16}, DecodeError::kBadAddressExtension);
}

// A frame whose framing is right but whose content DP refuses is offered whole to
// on_refused_frame (a sniffer keeps it), then its error follows; a frame with a wrong FCS is
// no frame and is not offered.
TEST(FdlDecoderResync, RefusedFrameIsOfferedWhole) {
  // Station 3 in segment 0x20 answers station 2 in segment 0x22: DA 02|80, SA 03|80, FC 08
  // (DL), DAE 62 and SAE 60 (bit 6 set: a segment address; bit 7 clear: no further byte
  // [IEC 61158-4-3 addresses, SAPs]), data 01 02. LE 7, FCS D2.
  const Bytes segment = {0x68, 0x07, 0x07, 0x68, 0x82, 0x83, 0x08,
                         0x62, 0x60, 0x01, 0x02, 0xD2, 0x16};
  const Bytes bad_fc = {0x10, 0x05, 0x02, 0x41, 0x48, 0x16};  // request function 1, FCS 48
  const Bytes bad_fcs = {0x68, 0x04, 0x04, 0x68, 0x05, 0x02, 0x7D, 0xA5, 0x2A, 0x16};  // 29
  for (const bool byte_by_byte : {false, true}) {
    SCOPED_TRACE(byte_by_byte ? "byte by byte" : "one chunk");
    Decoder d;
    CollectSink sink;
    feed(d, sink, concat({segment, kDx, bad_fc, bad_fcs, kDiagReq}), byte_by_byte);
    ASSERT_EQ(sink.refused.size(), 2U);
    EXPECT_EQ(sink.refused[0].first, segment);
    EXPECT_EQ(sink.refused[0].second, DecodeError::kBadAddressExtension);
    EXPECT_EQ(sink.refused[1].first, bad_fc);
    EXPECT_EQ(sink.refused[1].second, DecodeError::kBadFrameControl);
    EXPECT_EQ(sink.errors(),
              (std::vector<std::error_code>{DecodeError::kBadAddressExtension,
                                            DecodeError::kBadFrameControl, DecodeError::kBadFcs}));
    EXPECT_EQ(sink.telegrams().size(), 2U);
    EXPECT_EQ(d.stats().discarded_bytes, segment.size() + bad_fc.size() + bad_fcs.size());
  }
}

TEST(FdlDecoderResync, ReservedFrameControl) {
  expect_resync({0x10, 0x05, 0x02, 0x41, 0x48, 0x16},
                DecodeError::kBadFrameControl);  // request fn 1
  expect_resync({0x10, 0x02, 0x05, 0x04, 0x0B, 0x16}, DecodeError::kBadFrameControl);  // response 4
  expect_resync({0x10, 0x02, 0x05, 0x80, 0x87, 0x16},
                DecodeError::kBadFrameControl);  // bit 7 on a response
  expect_resync({0x10, 0x05, 0x02, 0xC3, 0xCA, 0x16},
                DecodeError::kBadFrameControl);  // bit 7 with SDA
  // Bit 7 with function 0 is a clock value (CV), which is legal.
  const Outcome cv = run({0x10, 0x05, 0x02, 0xC0, 0xC7, 0x16});
  EXPECT_TRUE(cv.sink.errors().empty());
  EXPECT_EQ(cv.sink.telegrams().size(), 1U);
}

TEST(FdlDecoderResync, TokenWithExtensionBit) {
  expect_resync({0xDC, 0x82, 0x02}, DecodeError::kBadTokenAddress);
}

TEST(FdlDecoderResync, CountersPerKind) {
  const Outcome o = run(concat({{0x00},
                                {0x68, 0x04, 0x04, 0x68, 0x05, 0x02, 0x7D, 0xA5, 0x2A, 0x16},
                                kDx,
                                {0x68, 0x05, 0x06, 0x00},
                                kDx,
                                {0x10, 0x05, 0x02, 0x41, 0x48, 0x16},
                                kDx}));
  EXPECT_EQ(o.stats.telegrams, 3U);
  EXPECT_EQ(o.stats.count(DecodeError::kGarbage), 1U);
  EXPECT_EQ(o.stats.count(DecodeError::kBadFcs), 1U);
  EXPECT_EQ(o.stats.count(DecodeError::kLengthMismatch), 1U);
  EXPECT_EQ(o.stats.count(DecodeError::kBadFrameControl), 1U);
  EXPECT_EQ(o.stats.total_errors(), 4U);
}

}  // namespace
}  // namespace rs4sim::dp::fdl
