// The barrier as Modbus slave against the manual's frames P1-P8 [Polaris manual §7.4]
// [Polaris manual §8.2.3], and its answer timing on the manual clock.
#include "tests/polaris/polaris_line.h"

#include <gtest/gtest.h>

#include <chrono>

namespace rs4sim::polaris {
namespace {

using std::chrono::microseconds;
using std::chrono::milliseconds;
using std::chrono::nanoseconds;
using namespace testing;  // Bytes, reply, Rig

std::vector<std::uint16_t> range(std::uint16_t first, std::uint16_t last) {
  std::vector<std::uint16_t> r;
  for (std::uint16_t b = first; b <= last; ++b) r.push_back(b);
  return r;
}

std::vector<std::uint16_t> join(std::vector<std::uint16_t> a, const std::vector<std::uint16_t>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

Options options(Family family, std::uint16_t beams, DataMode mode, std::uint8_t address) {
  Options o;
  o.family = family;
  o.beams = beams;
  o.mode = mode;
  o.address = address;
  return o;
}

TEST(PolarisSlave, P1AnsweredWithP2) {
  Rig h(options(Family::kPli02, 127, DataMode::k485Mb, 3));
  ASSERT_FALSE(h.device().set_interrupted(join(range(72, 79), range(87, 92)), h.now()));
  const Bytes p1{0x03,                    // slave 3
                 0x03,                    // FC 3
                 0x20, 0x00,              // start 0x2000
                 0x00, 0x08,              // 8 words
                 0x4E, 0x2E};             // CRC
  const Bytes p2{0x03, 0x03,              // slave 3, FC 3
                 0x10,                    // 16 bytes
                 0xFF, 0xFF, 0xFF, 0xFF,  // beams 1-32 free
                 0xFF, 0xFF, 0xFF, 0xFF,  // beams 33-64 free
                 0x80, 0x7F, 0xF0, 0x3F,  // 72-79 and 87-92 interrupted (LSB first)
                 0xFF, 0xFF, 0xFF, 0xFF,  // 97-127 free, 128 padding
                 0x1B, 0xD3};             // CRC 0xD31B
  const auto sent = reply(h, p1);
  ASSERT_TRUE(sent);
  EXPECT_EQ(sent->bytes, p2);
  EXPECT_EQ(h.device().counters().requests, 1U);
}

TEST(PolarisSlave, P3AnsweredWithP4) {
  Rig h(options(Family::kPl10, 40, DataMode::kFl4, 1));
  ASSERT_FALSE(h.device().set_interrupted(join(range(9, 13), range(25, 34)), h.now()));
  const Bytes p3{0x01, 0x03, 0x20, 0x00, 0x00, 0x0A, 0xCE, 0x0D};
  const Bytes p4{0x01, 0x03, 0x14,        // slave 1, FC 3, 20 bytes
                 0x00, 0x09, 0x00, 0x0D,  // object 1: 9..13
                 0x00, 0x19, 0x00, 0x22,  // object 2: 25..34
                 0x00, 0x00, 0x00, 0x00,  // object 3: none
                 0x00, 0x00, 0x00, 0x00,  // object 4: none
                 0x00, 0x09, 0x00, 0x22,  // overall 9..34
                 0x19, 0x5A};             // CRC
  const auto sent = reply(h, p3);
  ASSERT_TRUE(sent);
  EXPECT_EQ(sent->bytes, p4);
}

TEST(PolarisSlave, P3AnsweredWithP5) {
  // The FL4 screenshot [Polaris manual §7.4.3]: 2.5 mm barrier, objects 68-71 and 85-93.
  Rig h(options(Family::kPli02, 127, DataMode::kFl4, 1));
  ASSERT_FALSE(h.device().set_interrupted(join(range(68, 71), range(85, 93)), h.now()));
  const Bytes p5{0x01, 0x03, 0x14, 0x00, 0x44, 0x00, 0x47,  // object 1: 68..71
                 0x00, 0x55, 0x00, 0x5D,                    // object 2: 85..93
                 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
                 0x00, 0x00, 0x44, 0x00, 0x5D,  // overall 68..93
                 0x03, 0xB3};                   // CRC 0xB303
  const auto sent = reply(h, {0x01, 0x03, 0x20, 0x00, 0x00, 0x0A, 0xCE, 0x0D});
  ASSERT_TRUE(sent);
  EXPECT_EQ(sent->bytes, p5);
}

TEST(PolarisSlave, Fl1WithBothFunctionCodes) {
  Rig h(options(Family::kPl10, 40, DataMode::kFl1, 1));
  ASSERT_FALSE(h.device().set_interrupted(join(range(9, 13), range(25, 34)), h.now()));
  // FC 3, start 0x2000, 2 words -> P7: 4 bytes, overall 9..34.
  const auto fc3 = reply(h, {0x01, 0x03, 0x20, 0x00, 0x00, 0x02, 0xCF, 0xCB});
  ASSERT_TRUE(fc3);
  EXPECT_EQ(fc3->bytes, (Bytes{0x01, 0x03, 0x04, 0x00, 0x09, 0x00, 0x22, 0xAA, 0x28}));
  // P6: FC 4 gets the same data with FC 4 echoed.
  const auto fc4 = reply(h, {0x01, 0x04, 0x20, 0x00, 0x00, 0x02, 0x7A, 0x0B});
  ASSERT_TRUE(fc4);
  EXPECT_EQ(fc4->bytes, (Bytes{0x01, 0x04, 0x04, 0x00, 0x09, 0x00, 0x22, 0xAB, 0x9F}));
}

TEST(PolarisSlave, FlIgnoresTheWordCount) {
  Rig h(options(Family::kPl10, 40, DataMode::kFl1, 1));
  ASSERT_FALSE(h.device().set_interrupted(range(9, 34), h.now()));
  // start 0x2000, 0x7E words (outside 1..125): FL still answers its 2 words.
  const auto sent = reply(h, {0x01, 0x03, 0x20, 0x00, 0x00, 0x7E, 0xCE, 0x2A});
  ASSERT_TRUE(sent);
  EXPECT_EQ(sent->bytes, (Bytes{0x01, 0x03, 0x04, 0x00, 0x09, 0x00, 0x22, 0xAA, 0x28}));
}

TEST(PolarisSlave, MbWordCountBeyondTheBeamsPadsFree) {
  Rig h(options(Family::kPl10, 16, DataMode::k485Mb, 1));
  // 3 words asked of a 1-word block: FFFF FFFF FFFF (DECISION: padding = free beams).
  const auto sent = reply(h, {0x01, 0x03, 0x20, 0x00, 0x00, 0x03, 0x0E, 0x0B});
  ASSERT_TRUE(sent);
  EXPECT_EQ(sent->bytes, (Bytes{0x01, 0x03, 0x06, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x20, 0xFA}));
}

TEST(PolarisSlave, AnswersWhenTheScanInProgressEnds) {
  Options o = options(Family::kPl10, 16, DataMode::kFl1, 1);
  o.response_time = milliseconds(5);
  Rig h(o);
  const auto t0 = h.now();  // the first scan starts here
  h.run_for(milliseconds(1));
  h.send({0x01, 0x03, 0x20, 0x00});
  h.run_for(microseconds(500));  // the rest 0.5 ms later: still the same frame
  h.send({0x00, 0x02, 0xCF, 0xCB});
  // t3.5 at 19200 8N1 = 35 bit times = 1822.917 µs after the last byte.
  ASSERT_EQ(h.device().next_deadline(), h.now() + nanoseconds(1822917));
  h.run_to(*h.device().next_deadline());
  EXPECT_TRUE(h.quiet());  // the frame is complete, the answer waits for the scan
  EXPECT_EQ(h.device().next_deadline(), t0 + milliseconds(5));  // end of the first scan
  const auto sent = h.run_until_received(t0 + milliseconds(20));
  ASSERT_TRUE(sent);
  EXPECT_EQ(sent->start, t0 + milliseconds(5));
}

TEST(PolarisSlave, FixedGapAboveNineteenTwoHundred) {
  Options o = options(Family::kPl10, 16, DataMode::kFl1, 1);
  o.baud = 115200;
  Rig h(o);
  h.send({0x01, 0x03, 0x20, 0x00, 0x00, 0x02, 0xCF, 0xCB});
  EXPECT_EQ(h.device().next_deadline(), h.now() + microseconds(1750));
}

}  // namespace
}  // namespace rs4sim::polaris
