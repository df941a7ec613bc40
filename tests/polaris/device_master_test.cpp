// The barrier as Modbus master: an FC 16 push of its data every scan time, the slave's
// answer ignored [Polaris manual §8.1.1, §8.2.1].
#include "tests/polaris/polaris_line.h"

#include <gtest/gtest.h>

#include <chrono>

namespace rs4sim::polaris {
namespace {

using std::chrono::milliseconds;
using namespace testing;  // Bytes, Rig

Options master_fl4() {
  Options o;
  o.beams = 40;
  o.mode = DataMode::kFl4;
  o.role = Role::kMaster;
  o.address = 1;  // the slave it writes to
  o.scan_time = milliseconds(20);
  return o;
}

TEST(PolarisMaster, PushesFl4AtTheScanTime) {
  Rig h(master_fl4());
  const auto t0 = h.now();
  std::vector<std::uint16_t> beams;
  for (std::uint16_t b = 9; b <= 13; ++b) beams.push_back(b);
  for (std::uint16_t b = 25; b <= 34; ++b) beams.push_back(b);
  ASSERT_FALSE(h.device().set_interrupted(beams, t0));
  const Bytes push{0x01,                    // slave 1
                   0x10,                    // FC 16
                   0x00, 0x00,              // register 0 (master default)
                   0x00, 0x0A,              // 10 words
                   0x14,                    // 20 bytes
                   0x00, 0x09, 0x00, 0x0D,  // object 1: 9..13
                   0x00, 0x19, 0x00, 0x22,  // object 2: 25..34
                   0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
                   0x00, 0x00, 0x00, 0x09, 0x00, 0x22,  // overall 9..34
                   0xCA, 0xC3};
  EXPECT_EQ(h.device().next_deadline(), t0 + milliseconds(20));
  auto sent = h.run_until_received(t0 + milliseconds(100));
  ASSERT_TRUE(sent);
  EXPECT_EQ(sent->bytes, push);
  EXPECT_EQ(sent->start, t0 + milliseconds(20));
  sent = h.run_until_received(t0 + milliseconds(100));
  ASSERT_TRUE(sent);
  EXPECT_EQ(sent->start, t0 + milliseconds(40));
}

TEST(PolarisMaster, TheSlavesAnswerIsIgnored) {
  Rig h(master_fl4());
  const auto t0 = h.now();
  // The push at 20 ms has 29 characters: it has reached the slave 15.1 ms later.
  ASSERT_TRUE(h.run_until_received(t0 + milliseconds(36)));
  // The slave's FC 16 answer, then garbage 2 ms later (two frames: t3.5 is 1.82 ms):
  // framed, counted, nothing sent in reply before the next push at 40 ms.
  h.send({0x01, 0x10, 0x00, 0x00, 0x00, 0x0A, 0x40, 0x0E});
  h.run_for(milliseconds(2));
  h.send({0xDE, 0xAD});
  h.run_to(t0 + milliseconds(39));
  EXPECT_TRUE(h.quiet());
  EXPECT_EQ(h.device().counters().answers_ignored, 2U);
  const auto next = h.run_until_received(t0 + milliseconds(40) + testing::chars(h, 29));
  ASSERT_TRUE(next);
  EXPECT_EQ(next->start, t0 + milliseconds(40));
}

TEST(PolarisMaster, Mb485PushesTheBits) {
  Options o = master_fl4();
  o.mode = DataMode::k485Mb;
  o.beams = 16;
  o.start_address = 0x0100;
  Rig h(o);
  const std::vector<std::uint16_t> beams{1};
  ASSERT_FALSE(h.device().set_interrupted(beams, h.now()));
  // The push at 20 ms: 11 characters on the wire.
  const auto sent = h.run_until_received(h.now() + milliseconds(20) + testing::chars(h, 11));
  ASSERT_TRUE(sent);
  // 01 10, register 0x0100, 1 word, 2 bytes, FFFE (beam 1 = bit 0 interrupted), CRC.
  const Bytes head{0x01, 0x10, 0x01, 0x00, 0x00, 0x01, 0x02, 0xFF, 0xFE};
  EXPECT_EQ(Bytes(sent->bytes.begin(), sent->bytes.end() - 2), head);
}

TEST(PolarisMaster, FaultSkipsPushes) {
  Rig h(master_fl4());
  h.device().set_faults(Faults{false, {true, {}}});
  EXPECT_FALSE(h.run_until_received(h.now() + milliseconds(50)));
  EXPECT_FALSE(h.on_the_wire());
  EXPECT_EQ(h.device().counters().suppressed, 2U);
}

TEST(PolarisPn, ObjectAndHoleOutputs) {
  Options o;
  o.beams = 40;
  Rig h(o);
  const auto t0 = h.now();
  EXPECT_FALSE(h.device().pn1());
  const std::vector<std::uint16_t> one{5, 6};
  ASSERT_FALSE(h.device().set_interrupted(one, t0));
  EXPECT_TRUE(h.device().pn1());
  EXPECT_FALSE(h.device().pn2(t0));
  const std::vector<std::uint16_t> two{5, 6, 9};
  ASSERT_FALSE(h.device().set_interrupted(two, t0));
  EXPECT_TRUE(h.device().pn2(t0));
  const std::vector<std::uint16_t> bad{0, 41};
  EXPECT_TRUE(h.device().set_interrupted(bad, t0));

  o.detection = Detection::kHole;
  o.pn2_filter = 3;
  o.response_time = milliseconds(1);
  Rig hole(o);
  ASSERT_FALSE(hole.device().set_interrupted(two, t0));
  EXPECT_FALSE(hole.device().pn2(t0 + milliseconds(2)));
  EXPECT_TRUE(hole.device().pn2(t0 + milliseconds(3)));
}

}  // namespace
}  // namespace rs4sim::polaris
