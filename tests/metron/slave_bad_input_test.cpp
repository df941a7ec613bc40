// Bad input on the slave line: every corrupt, truncated, oversized or misaddressed message
// gets the manual's reaction (or the project's documented one), is counted, and the next
// good message is answered normally [METRON manual "No node", "With node"].
#include "tests/metron/metron_line.h"

#include <gtest/gtest.h>

namespace rs4sim::metron::testing {
namespace {

using namespace std::chrono_literals;

const Bytes kGood{0x02, 0x01, 0x0C, 0xF3};
const Bytes kGoodReply{0x02, 0x03, 0x0C, 0x01, 0x01, 0xF1};

void expect_next_good(Rig& rig) {
  const auto s = rig.exchange(kGood);
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(s[0].bytes, kGoodReply);
}

TEST(MetronBadInput, NoiseBeforeTheFrameStartIsSkipped) {
  Rig rig(slave_options());
  Bytes b{0x55, 0xAA, 0x00};
  b.insert(b.end(), kGood.begin(), kGood.end());
  const auto s = rig.exchange(b);
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(s[0].bytes, kGoodReply);
  EXPECT_EQ(rig.device().counters().noise_bytes, 3U);
}

// A parity error as it arrives from a link: the line reports the damaged character between
// the good ones (stream::ByteDevice::on_damaged_byte, a serial adapter with PARMRK) and the
// device rejects the whole message; without the hook the port would drop the byte (IGNPAR)
// and the device would wait for it, then count a truncated message instead.
TEST(MetronBadInput, ParityErrorRejectsTheMessageWithoutReply) {
  Rig rig(slave_options());
  rig.write(Bytes{0x02, 0x01, 0x0C});
  rig.write_damaged(0xF3);  // the checksum byte, received with a parity error
  rig.run_for(100ms);
  EXPECT_TRUE(rig.quiet());
  EXPECT_EQ(rig.line().counters().damaged_received, 1U);
  EXPECT_EQ(rig.device().counters().parity_rejected, 1U);
  EXPECT_EQ(rig.device().counters().truncated, 0U);
  expect_next_good(rig);
}

TEST(MetronBadInput, ParityErrorInTheMiddle) {
  Rig rig(slave_options());
  rig.write(Bytes{0x02});
  rig.write_damaged(0x01);  // the length byte
  rig.write(Bytes{0x0C, 0xF3});
  rig.run_for(100ms);
  EXPECT_TRUE(rig.quiet());
  EXPECT_EQ(rig.device().counters().parity_rejected, 1U);
  expect_next_good(rig);
}

TEST(MetronBadInput, TruncatedMessageIsDroppedAfterTheTimeout) {
  Rig rig(slave_options());
  rig.send({0x02, 0x02, 0x09});  // two bytes short
  rig.run_for(25ms);             // receive timeout 20 ms
  EXPECT_TRUE(rig.quiet());
  EXPECT_EQ(rig.device().counters().truncated, 1U);
  expect_next_good(rig);
}

TEST(MetronBadInput, OversizedLengthThenGoodFrame) {
  Rig rig(slave_options());
  Bytes b{0x02, 0xF0};
  b.insert(b.end(), 40, 0x02);  // garbage full of frame-start characters
  const auto s = rig.exchange(b);
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(s[0].bytes, (Bytes{0x02, 0x01, 0xE1, 0x1E}));
  expect_next_good(rig);
  EXPECT_EQ(rig.device().counters().messages, 2U);
}

TEST(MetronBadInput, MisaddressedFrameWithStartBytesInsideIsSkippedWhole) {
  Rig rig(node_options(5));
  // to node 2: #7 with field 0x02 -- the data byte equals the frame start
  EXPECT_TRUE(rig.silent({0x02, 0x02, 0x02, 0x07, 0x02, 0xF6}));
  EXPECT_EQ(rig.device().counters().not_for_us, 1U);
  const auto r = rig.exchange({0x02, 0x05, 0x01, 0x0C, 0xF3});
  ASSERT_EQ(r.size(), 1U);
}

TEST(MetronBadInput, TwoMessagesInOneChunkAreBothAnswered) {
  Rig rig(slave_options());
  Bytes b = kGood;
  b.insert(b.end(), {0x02, 0x01, 0x0D, 0xF2});
  const auto s = rig.exchange(b);
  ASSERT_EQ(s.size(), 2U);
  EXPECT_EQ(s[0].bytes, kGoodReply);
  EXPECT_EQ(s[1].bytes, (Bytes{0x02, 0x02, 0x0D, 0x03, 0xEF}));
}

TEST(MetronBadInput, BadChecksumDoesNotDisturbTheNextMessage) {
  Rig rig(slave_options());
  rig.exchange({0x02, 0x01, 0x0C, 0x00});
  expect_next_good(rig);
}

TEST(MetronBadInput, StandardModeIgnoresOtherBytes) {
  auto o = slave_options();
  o.line_mode = LineMode::kStandard;
  o.reporting_mode = ReportingMode::kOnRequest;
  Rig rig(o);
  rig.send({0x00, 0x41, 0xFF});
  rig.run_for(50ms);
  EXPECT_TRUE(rig.quiet());
  EXPECT_EQ(rig.device().counters().other_bytes, 3U);
}

}  // namespace
}  // namespace rs4sim::metron::testing
