// The streaming decoder on bytes read off a real PROFIBUS line (docs/capture.md "Real bus
// traffic"): the NIKI 4.0 project's capture of a master (address 4) polling about 18 slaves,
// with stretches of line noise, read from the real material beside the repository
// (tests/real_material.h). The known answer comes from outside the decoder: a count by a
// separate script that only checks, at every byte, whether an SD1 or SD2 frame starts there
// whose length fields, FCS and end delimiter are right [IEC 61158-4-3 frame formats, FCS]
// (and steps over each frame it finds): 15,727 SD1 and 34,833 SD2 frames.
#include "hex_capture.h"
#include "line_frames.h"
#include "tests/real_material.h"

#include <gtest/gtest.h>

namespace rs4sim::dp::fdl {
namespace {

using testing::LineFrames;

std::vector<std::uint8_t> niki40_bytes() {
  const auto path = rs4sim::testing::real_file("captures/niki40-bus.txt");
  if (!path) return {};
  std::string error;
  const auto capture = testing::read_hex_capture(*path, error);
  EXPECT_TRUE(capture) << error;
  if (!capture) return {};
  // Counted by hand: 2,607,021 hex digits follow the header, an odd number; the last digit is
  // half a byte and is dropped.
  EXPECT_EQ(capture->digits, 2'607'021U);
  return capture->bytes;
}

std::string absent() {
  return "the real capture captures/niki40-bus.txt is absent from " +
         rs4sim::testing::real_material_dir().string() + " (RS4SIM_REAL_DIR names another place)";
}

TEST(FdlDecoderRealLine, FindsEveryFrameOfTheNiki40Capture) {
  const auto bytes = niki40_bytes();
  if (bytes.empty()) GTEST_SKIP() << absent();
  ASSERT_EQ(bytes.size(), 1'303'510U);
  const LineFrames line(bytes);
  EXPECT_EQ(line.count(kSd1), 15'727U);
  EXPECT_EQ(line.count(kSd2), 34'833U);
  EXPECT_EQ(line.mismatches, 0U) << "a telegram that does not re-encode to the line's bytes";
  // One of the SD2 frames addresses both stations with a segment address (DA and SA with the
  // extension bit, extension bytes with bit 6 set) [IEC 61158-4-3 addresses, SAPs]: right
  // framing, content DP does not use; the decoder refuses it and offers it whole.
  std::vector<testing::LineFrame> refused;
  for (const auto& f : line.frames) {
    if (f.refused) refused.push_back(f);
  }
  ASSERT_EQ(refused.size(), 1U);
  EXPECT_EQ(refused[0].bytes[0], kSd2);
  EXPECT_EQ(refused[0].refused, DecodeError::kBadAddressExtension);
  EXPECT_EQ(refused[0].bytes[7] & 0xC0, 0x40) << "DAE: a segment address";
  EXPECT_EQ(line.stats().count(DecodeError::kBadAddressExtension), 1U);
  EXPECT_EQ(line.stats().count(DecodeError::kBadFrameControl), 0U);
  // Every byte is accounted for: in a frame found, or discarded as noise.
  std::size_t in_frames = 0;
  for (const auto& f : line.frames) in_frames += f.refused ? 0U : f.bytes.size();
  EXPECT_EQ(in_frames + line.stats().discarded_bytes, bytes.size());
}

// The same telegrams and errors whatever the chunks the line arrives in (one read of the
// whole capture, or reads of 7 bytes) as byte by byte.
TEST(FdlDecoderRealLine, ChunkingDoesNotMatter) {
  const auto bytes = niki40_bytes();
  if (bytes.empty()) GTEST_SKIP() << absent();
  const LineFrames by_byte(bytes);
  for (const std::size_t chunk : {bytes.size(), std::size_t{7}}) {
    SCOPED_TRACE(chunk);
    struct Counting final : DecoderSink {
      void on_telegram(const Telegram&) override {}
    } sink;
    Decoder d;
    for (std::size_t pos = 0; pos < bytes.size(); pos += chunk) {
      d.feed(std::span(bytes).subspan(pos, std::min(chunk, bytes.size() - pos)), sink);
    }
    d.idle(sink);
    EXPECT_EQ(d.stats().telegrams, by_byte.stats().telegrams);
    EXPECT_EQ(d.stats().errors, by_byte.stats().errors);
    EXPECT_EQ(d.stats().discarded_bytes, by_byte.stats().discarded_bytes);
  }
}

}  // namespace
}  // namespace rs4sim::dp::fdl
