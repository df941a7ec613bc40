// Bad frames get the manual's reaction, are counted, and never disturb the next good
// frame [Polaris manual §8.1.2]; the fault controls change what the controller sees.
#include "tests/polaris/polaris_line.h"

#include <gtest/gtest.h>

#include <chrono>

namespace rs4sim::polaris {
namespace {

using std::chrono::milliseconds;
using namespace testing;  // Bytes, reply, Rig

const Bytes kGoodFl1{0x01, 0x03, 0x20, 0x00, 0x00, 0x02, 0xCF, 0xCB};
const Bytes kFl1Answer{0x01, 0x03, 0x04, 0x00, 0x09, 0x00, 0x22, 0xAA, 0x28};

Options fl1(bool nak = true) {
  Options o;
  o.beams = 40;
  o.mode = DataMode::kFl1;
  o.nak_on_error = nak;
  return o;
}

Rig& with_scene(Rig& h) {
  const std::vector<std::uint16_t> beams{9, 34};
  EXPECT_FALSE(h.device().set_interrupted(beams, h.now()));
  return h;
}

void expect_next_good(Rig& h) {
  const auto sent = reply(h, kGoodFl1);
  ASSERT_TRUE(sent);
  EXPECT_EQ(sent->bytes, (Bytes{0x01, 0x03, 0x04, 0x00, 0x09, 0x00, 0x22, 0xAA, 0x28}));
}

TEST(PolarisErrors, P8CrcErrorGetsNegativeAcknowledge) {
  Options o;
  o.address = 3;
  Rig h(o);
  // P1 with its CRC's bytes swapped -> P8: slave 3, FC 3|0x80, code 07, CRC A1 32.
  const auto sent = reply(h, {0x03, 0x03, 0x20, 0x00, 0x00, 0x08, 0x2E, 0x4E});
  ASSERT_TRUE(sent);
  EXPECT_EQ(sent->bytes, (Bytes{0x03, 0x83, 0x07, 0xA1, 0x32}));
  EXPECT_EQ(h.device().counters().crc_errors, 1U);
  EXPECT_EQ(h.device().counters().exceptions_sent, 1U);
}

TEST(PolarisErrors, StandardSilenceOnCrcError) {
  Rig h(fl1(false));
  with_scene(h);
  EXPECT_TRUE(h.silent({0x01, 0x03, 0x20, 0x00, 0x00, 0x02, 0xCB, 0xCF}, milliseconds(50)));
  EXPECT_EQ(h.device().counters().crc_errors, 1U);
  expect_next_good(h);
}

TEST(PolarisErrors, BadFunction) {
  Rig nak(fl1());
  // FC 5 write single coil (FC 6/16 now write the configuration registers): exception 07
  // (the manual) ...
  const Bytes fc5{0x01, 0x05, 0x20, 0x00, 0x00, 0x01, 0x07, 0xCA};
  auto sent = reply(nak, fc5);
  ASSERT_TRUE(sent);
  EXPECT_EQ(sent->bytes, (Bytes{0x01, 0x85, 0x07, 0x03, 0x52}));
  // ... or 01 illegal function (standard Modbus).
  Rig standard(fl1(false));
  sent = reply(standard, fc5);
  ASSERT_TRUE(sent);
  EXPECT_EQ(sent->bytes, (Bytes{0x01, 0x85, 0x01, 0x83, 0x50}));
  EXPECT_EQ(standard.device().counters().bad_function, 1U);
}

TEST(PolarisErrors, StartOutsideTheBlock) {
  Rig h(fl1());
  with_scene(h);
  // start 0x1FFF: below the block -> exception 02.
  const auto sent = reply(h, {0x01, 0x03, 0x1F, 0xFF, 0x00, 0x01, 0xB3, 0xEE});
  ASSERT_TRUE(sent);
  EXPECT_EQ(sent->bytes, (Bytes{0x01, 0x83, 0x02, 0xC0, 0xF1}));
  // start 0x2001: inside, the rest of the block (the last word, 34).
  const auto inside = reply(h, {0x01, 0x03, 0x20, 0x01, 0x00, 0x02, 0x9E, 0x0B});
  ASSERT_TRUE(inside);
  EXPECT_EQ(inside->bytes.size(), 7U);
  EXPECT_EQ(inside->bytes[2], 0x02);
  EXPECT_EQ(inside->bytes[4], 0x22);
  EXPECT_EQ(h.device().counters().bad_start, 1U);
}

TEST(PolarisErrors, MbWordCountOutOfRange) {
  Options o;  // 485MB
  Rig h(o);
  const auto sent = reply(h, {0x01, 0x03, 0x20, 0x00, 0x00, 0x7E, 0xCE, 0x2A});
  ASSERT_TRUE(sent);
  EXPECT_EQ(sent->bytes, (Bytes{0x01, 0x83, 0x03, 0x01, 0x31}));
  EXPECT_EQ(h.device().counters().bad_request, 1U);
}

TEST(PolarisErrors, IgnoredFramesAreCounted) {
  Rig h(fl1());
  with_scene(h);
  EXPECT_TRUE(h.silent({0x01, 0x03, 0x20}, milliseconds(50)));  // too short
  EXPECT_TRUE(h.silent(Bytes(300, 0x01), milliseconds(50)));    // oversized
  const auto& c = h.device().counters();
  EXPECT_EQ(c.too_short, 1U);
  EXPECT_EQ(c.oversized, 1U);
  expect_next_good(h);
}

TEST(PolarisErrors, ForeignAndBroadcastAreSilent) {
  Rig h(fl1());
  with_scene(h);
  // slave 2, FC 3, start 0x2000, 2 words, CRC CF F8
  EXPECT_TRUE(h.silent({0x02, 0x03, 0x20, 0x00, 0x00, 0x02, 0xCF, 0xF8}, milliseconds(50)));
  // broadcast (address 0: not supported by the Polaris), CRC CE 1A
  EXPECT_TRUE(h.silent({0x00, 0x03, 0x20, 0x00, 0x00, 0x02, 0xCE, 0x1A}, milliseconds(50)));
  EXPECT_EQ(h.device().counters().foreign_address, 1U);
  EXPECT_EQ(h.device().counters().broadcasts, 1U);
  expect_next_good(h);
}

TEST(PolarisErrors, FaultBadCrc) {
  Rig h(fl1());
  with_scene(h);
  h.device().set_faults(Faults{true, {false, {}}});
  const auto sent = reply(h, kGoodFl1);
  ASSERT_TRUE(sent);
  Bytes expected = kFl1Answer;
  expected.back() = static_cast<std::uint8_t>(~expected.back());
  EXPECT_EQ(sent->bytes, expected);
}

TEST(PolarisErrors, FaultNoAnswerThenLate) {
  Options o = fl1();
  o.response_time = milliseconds(2);
  Rig h(o);
  with_scene(h);
  h.device().set_faults(Faults{false, {true, {}}});
  EXPECT_TRUE(h.silent(kGoodFl1, milliseconds(50)));
  EXPECT_EQ(h.device().counters().suppressed, 1U);
  h.device().set_faults(Faults{false, {false, milliseconds(30)}});
  const auto start = h.now();
  const auto sent = reply(h, kGoodFl1, milliseconds(100));
  ASSERT_TRUE(sent);
  EXPECT_EQ(sent->bytes, kFl1Answer);
  EXPECT_GE(sent->start - start, milliseconds(30));
  EXPECT_LE(sent->start - start, milliseconds(30) + milliseconds(4));
}

}  // namespace
}  // namespace rs4sim::polaris
