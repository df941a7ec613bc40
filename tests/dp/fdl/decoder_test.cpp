// Streaming decoder: chunking (byte by byte, every split point, merged frames), counters,
// idle handling. [IEC 61158-4-3 frame formats, frame reception], vectors from
// [docs/references.md#dp-worked-example].
#include "collect_sink.h"

#include <gtest/gtest.h>

namespace rs4sim::dp::fdl {
namespace {

using testing::Bytes;
using testing::CollectSink;
using testing::concat;

// The [docs/references.md#dp-worked-example] start-up session, master 2 ↔ slave 5, in bus order.
const std::vector<Bytes> kSession = {
    {0x10, 0x05, 0x02, 0x49, 0x50, 0x16},                                // FDL_Status
    {0x10, 0x02, 0x05, 0x00, 0x07, 0x16},                                // reply
    {0x68, 0x05, 0x05, 0x68, 0x85, 0x82, 0x6D, 0x3C, 0x3E, 0xEE, 0x16},  // Slave_Diag
    {0x68, 0x0B, 0x0B, 0x68, 0x82, 0x85, 0x08, 0x3E, 0x3C, 0x02, 0x05, 0x00, 0xFF, 0x12, 0x34, 0xD5,
     0x16},
    {0x68, 0x0F, 0x0F, 0x68, 0x85, 0x82, 0x5D, 0x3D, 0x3E, 0x88, 0x0A,
     0x01, 0x0B, 0x12, 0x34, 0x00, 0x80, 0x20, 0x00, 0x63, 0x16},                    // Set_Prm
    {0xE5},                                                                          // SC
    {0x68, 0x07, 0x07, 0x68, 0x85, 0x82, 0x7D, 0x3E, 0x3E, 0x10, 0x20, 0x30, 0x16},  // Chk_Cfg
    {0xE5},
    {0xA2, 0x82, 0x85, 0x08, 0x3E, 0x3C, 0x00, 0x0C, 0x00, 0x02, 0x12, 0x34, 0xDD,
     0x16},                                                                          // diag as SD3
    {0x68, 0x04, 0x04, 0x68, 0x05, 0x02, 0x7D, 0xA5, 0x29, 0x16},                    // DX
    {0x68, 0x04, 0x04, 0x68, 0x02, 0x05, 0x08, 0x3C, 0x4B, 0x16},                    // DX reply
    {0xDC, 0x02, 0x02},                                                              // token
    {0x68, 0x07, 0x07, 0x68, 0xFF, 0x82, 0x46, 0x3A, 0x3E, 0x02, 0x00, 0x41, 0x16},  // GC Clear
};

Bytes session_stream() {
  Bytes all;
  for (const auto& f : kSession) all.insert(all.end(), f.begin(), f.end());
  return all;
}

// Every telegram re-encodes to exactly the frame it came from.
void expect_session(const CollectSink& sink) {
  ASSERT_TRUE(sink.errors().empty()) << sink.errors().front().message();
  const auto ts = sink.telegrams();
  ASSERT_EQ(ts.size(), kSession.size());
  for (std::size_t i = 0; i < ts.size(); ++i) {
    Bytes re;
    encode(ts[i], re);
    EXPECT_EQ(re, kSession[i]) << "telegram " << i;
  }
}

TEST(FdlDecoder, WholeStreamInOneChunk) {
  Decoder d;
  CollectSink sink;
  d.feed(session_stream(), sink);
  expect_session(sink);
  EXPECT_EQ(d.stats().telegrams, kSession.size());
  EXPECT_EQ(d.stats().bytes, session_stream().size());
  EXPECT_EQ(d.pending_bytes(), 0U);
}

TEST(FdlDecoder, ByteByByte) {
  Decoder d;
  CollectSink sink;
  for (const std::uint8_t b : session_stream()) d.feed(std::span<const std::uint8_t>(&b, 1), sink);
  expect_session(sink);
}

TEST(FdlDecoder, EveryTwoChunkSplit) {
  const Bytes all = session_stream();
  for (std::size_t cut = 0; cut <= all.size(); ++cut) {
    Decoder d;
    CollectSink sink;
    d.feed(std::span<const std::uint8_t>(all).first(cut), sink);
    d.feed(std::span<const std::uint8_t>(all).subspan(cut), sink);
    SCOPED_TRACE(cut);
    expect_session(sink);
  }
}

TEST(FdlDecoder, IrregularChunksLargerThanTheInternalBuffer) {
  Bytes all;
  for (int i = 0; i < 20; ++i) {
    const Bytes s = session_stream();
    all.insert(all.end(), s.begin(), s.end());
  }
  Decoder d;
  CollectSink sink;
  std::size_t pos = 0;
  std::size_t chunk = 1;
  while (pos < all.size()) {
    const std::size_t n = std::min(chunk, all.size() - pos);
    d.feed(std::span<const std::uint8_t>(all).subspan(pos, n), sink);
    pos += n;
    chunk = (chunk * 7 + 3) % 600 + 1;  // 1…600 bytes, crossing the 510-byte buffer
  }
  EXPECT_TRUE(sink.errors().empty());
  EXPECT_EQ(sink.telegrams().size(), 20 * kSession.size());
}

TEST(FdlDecoder, PartialFrameWaitsThenCompletes) {
  const Bytes& diag = kSession[3];
  Decoder d;
  CollectSink sink;
  d.feed(std::span<const std::uint8_t>(diag).first(10), sink);
  EXPECT_TRUE(sink.events.empty());
  EXPECT_EQ(d.pending_bytes(), 10U);
  d.feed(std::span<const std::uint8_t>(diag).subspan(10), sink);
  ASSERT_EQ(sink.telegrams().size(), 1U);
  EXPECT_EQ(d.pending_bytes(), 0U);
}

TEST(FdlDecoder, IdleInsideAFrameReportsTruncated) {
  const Bytes& diag = kSession[3];
  Decoder d;
  CollectSink sink;
  d.feed(std::span<const std::uint8_t>(diag).first(7), sink);
  d.idle(sink);
  ASSERT_EQ(sink.errors().size(), 1U);
  EXPECT_EQ(sink.errors()[0], DecodeError::kTruncated);
  EXPECT_EQ(d.stats().count(DecodeError::kTruncated), 1U);
  EXPECT_EQ(d.stats().discarded_bytes, 7U);
  // The line is clean again: the next frame decodes.
  d.feed(kSession[2], sink);
  EXPECT_EQ(sink.telegrams().size(), 1U);
  d.idle(sink);  // idle with nothing pending is silent
  EXPECT_EQ(sink.errors().size(), 1U);
}

TEST(FdlDecoder, ResetDropsSilently) {
  Decoder d;
  CollectSink sink;
  d.feed(std::span<const std::uint8_t>(kSession[3]).first(5), sink);
  d.reset();
  d.feed(kSession[2], sink);
  EXPECT_TRUE(sink.errors().empty());
  EXPECT_EQ(sink.telegrams().size(), 1U);
}

TEST(FdlDecoder, ErrorCategoryHasReadableMessages) {
  const std::error_code ec = DecodeError::kBadFcs;
  EXPECT_STREQ(ec.category().name(), "fdl.decode");
  EXPECT_EQ(ec.message(), "frame check sequence mismatch");
  EXPECT_NE(std::error_code(DecodeError::kGarbage).message(), ec.message());
}

TEST(FdlDecoder, DecodeFrameRejectsTrailingBytesAndTruncation) {
  Telegram t;
  const Bytes two = concat({kSession[5], kSession[5]});
  EXPECT_EQ(decode_frame(two, t), DecodeError::kGarbage);
  EXPECT_EQ(decode_frame(std::span<const std::uint8_t>(kSession[3]).first(8), t),
            DecodeError::kTruncated);
  EXPECT_EQ(decode_frame({}, t), DecodeError::kTruncated);
}

}  // namespace
}  // namespace rs4sim::dp::fdl

// Decoder::feed_encoded (the memory bus's path for a frame no fault touched) must give the
// sink and the statistics exactly what feed() of the encoded bytes gives: for every FC byte
// (undefined codes are rejected by the receiver check, [IEC 61158-4-3 frame reception]), every
// frame shape, short acknowledgements and tokens carrying fields the wire drops, and with a
// partial frame pending in the decoder.
namespace rs4sim::dp::fdl {
namespace {

std::vector<Telegram> feed_encoded_cases() {
  std::vector<Telegram> cases;
  const std::vector<std::uint8_t> two{0x5A, 0xE5}, six{1, 2, 3, 4, 5, 6}, eight{1, 2, 3, 4, 5, 6, 7, 8};
  for (unsigned fc = 0; fc < 256; ++fc) {
    const FrameControl f{static_cast<std::uint8_t>(fc)};
    cases.push_back(make_data_telegram(5, 2, f, std::nullopt, std::nullopt, {}));  // SD1
    cases.push_back(make_data_telegram(5, 2, f, std::nullopt, std::nullopt, two));
    cases.push_back(make_data_telegram(127, 2, f, 58, 62, two));
    cases.push_back(make_data_telegram(2, 5, f, 62, 60, {}));  // SD2, SAPs only
    Telegram sd3 = make_data_telegram(2, 5, f, 62, 60, six);
    sd3.type = FrameType::kSd3;
    cases.push_back(sd3);
    Telegram sd3_plain = make_data_telegram(2, 5, f, std::nullopt, std::nullopt, eight);
    sd3_plain.type = FrameType::kSd3;
    cases.push_back(sd3_plain);
    Telegram sc = make_short_ack();
    sc.fc = f;  // dropped on the wire
    cases.push_back(sc);
    Telegram token = make_token(2, 2);
    token.fc = f;
    cases.push_back(token);
  }
  Telegram sc_addressed = make_short_ack();
  sc_addressed.da = 5;
  cases.push_back(sc_addressed);
  Telegram token_with_data = make_token(3, 2);
  token_with_data.data.push_back(1);
  cases.push_back(token_with_data);
  Telegram longest = make_data_telegram(5, 2, FrameControl{0x7D}, 1, 2,
                                        std::vector<std::uint8_t>(kMaxDataUnit - 2, 0xE5));
  cases.push_back(longest);
  return cases;
}

void expect_same_as_feed(const Telegram& t, const Bytes& before) {
  std::vector<std::uint8_t> wire;
  encode(t, wire);
  Decoder parsed, fast;
  testing::CollectSink parsed_sink, fast_sink;
  parsed.feed(before, parsed_sink);
  fast.feed(before, fast_sink);
  parsed.feed(wire, parsed_sink);
  fast.feed_encoded(t, fast_sink);
  ASSERT_EQ(fast_sink.telegrams(), parsed_sink.telegrams());
  ASSERT_EQ(fast_sink.errors(), parsed_sink.errors());
  ASSERT_EQ(fast_sink.events.size(), parsed_sink.events.size());
  EXPECT_EQ(fast.stats().bytes, parsed.stats().bytes);
  EXPECT_EQ(fast.stats().telegrams, parsed.stats().telegrams);
  EXPECT_EQ(fast.stats().discarded_bytes, parsed.stats().discarded_bytes);
  EXPECT_EQ(fast.stats().errors, parsed.stats().errors);
  EXPECT_EQ(fast.pending_bytes(), parsed.pending_bytes());
  // Whatever follows is treated alike, too (the garbage state after a rejected frame).
  const Bytes garbage{0x00, 0x01};
  parsed.feed(garbage, parsed_sink);
  fast.feed(garbage, fast_sink);
  EXPECT_EQ(fast_sink.errors(), parsed_sink.errors());
  EXPECT_EQ(fast.stats().errors, parsed.stats().errors);
}

TEST(DecoderFeedEncoded, DeliversExactlyWhatDecodingTheEncodedBytesDelivers) {
  std::size_t fast_path = 0;
  for (const Telegram& t : feed_encoded_cases()) {
    SCOPED_TRACE(::testing::Message() << "type " << static_cast<int>(t.type) << " fc 0x"
                                      << std::hex << int{t.fc.raw});
    expect_same_as_feed(t, {});
    expect_same_as_feed(t, {0x00});                    // after garbage
    expect_same_as_feed(t, {0x68, 0x05, 0x05, 0x68});  // a partial frame pending
    if (decodes_as_itself(t)) ++fast_path;
  }
  EXPECT_GT(fast_path, 0U);
}

TEST(DecoderFeedEncoded, OnlyTelegramsTheWireKeepsWholeTakeTheFastPath) {
  EXPECT_TRUE(decodes_as_itself(make_short_ack()));
  EXPECT_TRUE(decodes_as_itself(make_token(2, 2)));
  Telegram sc = make_short_ack();
  sc.da = 5;
  EXPECT_FALSE(decodes_as_itself(sc));
  // Request code 1 and response code 4 are undefined ([IEC 61158-4-3 frame control]).
  EXPECT_FALSE(decodes_as_itself(make_data_telegram(5, 2, FrameControl{0x41}, {}, {}, {})));
  EXPECT_FALSE(decodes_as_itself(make_data_telegram(2, 5, FrameControl{0x04}, {}, {}, {})));
  EXPECT_TRUE(decodes_as_itself(make_data_telegram(5, 2, FrameControl{0x7D}, {}, {}, {})));
}

}  // namespace
}  // namespace rs4sim::dp::fdl
