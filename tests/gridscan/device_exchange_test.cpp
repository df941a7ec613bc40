// The device from power-up through the whole [GridScan manual §10.3] exchange, byte for
// byte and on the manual clock: power-up messages, answers after the cycle end, one
// request per cycle, the sequence counter rules ([GridScan manual §9.2.2, §10.1.1, §11]).
#include "tests/gridscan/gridscan_line.h"

namespace rs4sim::gridscan::testing {
namespace {

const Bytes kPowerUpVersion{0x43, 0x45, 0x44, 0x45,        // sync
                            0x00,                          // SeqCnt 0 (DECISION)
                            0xA0,                          // Info: Get version, answer
                            0x30, 0x31, 0x2E, 0x30, 0x32,  // SW "01.02"
                            0x30, 0x33, 0x2E, 0x30, 0x34,  // HW "03.04"
                            0x33, 0x7F, 0x67, 0x4B};       // CRC

TEST(GridScanExchange, PowerUpThenTheManualsCommunicationTest) {
  Rig h(Options{});  // powers up as the line starts
  const auto t0 = h.now();
  EXPECT_EQ(h.device().power(), PowerState::kStarting);
  h.run_to(t0 + chars(20));  // the version message's 20 characters
  auto s = h.take();
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(s[0].bytes, kPowerUpVersion);
  EXPECT_EQ(s[0].start, t0);

  h.run_to(t0 + 1700ms + chars(12));  // ready: Data: Reduced state, SeqCnt 1
  s = h.take();
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(s[0].start, t0 + 1700ms);
  EXPECT_EQ(s[0].bytes, (Bytes{0x43, 0x45, 0x44, 0x45,     // sync
                               0x01,                       // SeqCnt 1 (DECISION)
                               0xB0,                       // Data: Reduced state
                               0x16, 0x00,                 // door 22 open, clear, clean
                               0x69, 0x78, 0x27, 0x24}));  // CRC (COMPUTED)
  const auto ready = t0 + 1700ms;

  struct Step {
    Bytes request, answer;
  };
  const std::vector<Step> steps{
      {{0x00, 0x00, 0x00, 0x00, 0x00, 0x23, 0x00, 0x00, 0x00, 0x00},  // all wrong
       {0x43, 0x45, 0x44, 0x45, 0x01, 0xA3, 0x07, 0xEF, 0x30, 0x3F, 0x78}},
      {{0x00, 0x00, 0x00, 0x00, 0x02, 0x23, 0x00, 0x00, 0x00, 0x00},  // SeqCnt 2 = 1 + 1
       {0x43, 0x45, 0x44, 0x45, 0x03, 0xA3, 0x05, 0x8F, 0x52, 0x0C, 0x72}},
      {{0x43, 0x45, 0x44, 0x45, 0x04, 0x23, 0x00, 0x00, 0x00, 0x00},  // sync now right
       {0x43, 0x45, 0x44, 0x45, 0x05, 0xA3, 0x01, 0x41, 0xCF, 0xDB, 0x65}},
      {{0x43, 0x45, 0x44, 0x45, 0x06, 0x23, 0xE2, 0x4B, 0x01, 0x70},  // CRC now right
       {0x43, 0x45, 0x44, 0x45, 0x07, 0xA3, 0x00, 0xF8, 0x8B, 0xAB, 0x62}},
  };
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const auto cycle_end = ready + 30ms * static_cast<int>(i + 1);
    h.run_to(cycle_end - 25ms);  // 5 ms into cycle i
    h.send(steps[i].request);
    h.run_to(cycle_end - 1ms);  // still inside the cycle: nothing given out yet
    EXPECT_TRUE(h.quiet()) << "step " << i;
    h.run_to(cycle_end + chars(11));  // the answer leaves at the cycle end: 11 characters
    s = h.take();
    ASSERT_EQ(s.size(), 1U) << "step " << i;
    EXPECT_EQ(s[0].bytes, steps[i].answer) << "step " << i;
    EXPECT_EQ(s[0].start, cycle_end) << "step " << i;
  }
  EXPECT_EQ(h.device().counters().comm_tests, 4U);
  EXPECT_EQ(h.device().counters().dropped(), 0U);
}

TEST(GridScanExchange, RequestsBeforeReadyAreDropped) {
  Rig h(Options{});
  h.run_for(100ms);
  (void)h.take();  // the version message
  h.send(request(2, CommandId::kInfoCommunicationTest));
  h.run_for(1000ms);
  EXPECT_TRUE(h.quiet());
  EXPECT_EQ(h.device().counters().not_ready, 1U);
}

TEST(GridScanExchange, SequenceCounterRulesAndWrap) {
  Rig h(Options{});
  boot(h);
  EXPECT_TRUE(h.silent(request(3, CommandId::kInfoGetCountOfElements)));  // expected 2
  EXPECT_EQ(h.device().counters().bad_seq, 1U);
  auto s = h.exchange(request(2, CommandId::kInfoGetCountOfElements));
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(decode_response(s[0].bytes, 22).value(), (Frame{3, 0xA2, {22}}));
  // Walk the counter to the wrap: request 254 → answer 255, request 0 → answer 1.
  std::uint8_t next = 4;
  while (next != 0) {
    s = h.exchange(request(next, CommandId::kModeGetCurrent), 40ms);
    ASSERT_EQ(s.size(), 1U) << int{next};
    EXPECT_EQ(s[0].bytes[4], static_cast<std::uint8_t>(next + 1));
    next = static_cast<std::uint8_t>(next + 2);
  }
  s = h.exchange(request(0, CommandId::kModeGetCurrent));
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(decode_response(s[0].bytes, 22).value(), (Frame{1, 0x94, {0}}));
}

TEST(GridScanExchange, OneRequestPerCycle) {
  Rig h(Options{});
  boot(h);
  h.run_for(2ms);
  h.send(request(2, CommandId::kInfoGetCountOfElements));
  h.run_for(5ms);
  h.send(request(4, CommandId::kInfoGetCountOfElements));  // same cycle: dropped
  h.run_for(60ms);
  ASSERT_EQ(h.take().size(), 1U);
  EXPECT_EQ(h.device().counters().busy, 1U);
  // The next good frame is answered in the next cycle.
  auto s = h.exchange(request(4, CommandId::kInfoGetCountOfElements));
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(s[0].bytes[4], 5);
}

TEST(GridScanExchange, BadInputIsCountedAndNeverDisturbsTheNextGoodFrame) {
  Rig h(Options{});
  boot(h);
  const Bytes good = request(2, CommandId::kInfoGetCountOfElements);
  Bytes bad_crc = good;
  bad_crc[9] ^= 0xFF;
  Bytes bad_sync = good;
  bad_sync[0] = 0x00;
  const std::vector<Bytes> bad{
      Bytes(good.begin(), good.begin() + 9),  // truncated
      [&] {
        Bytes b = good;
        b.push_back(0);
        return b;
      }(),              // 11 bytes
      Bytes(40, 0x43),  // oversized beyond 20
      bad_crc,
      bad_sync,
      encode({2, 0xA2, {}}),  // direction bit set in a request
      encode({2, 0x26, {}}),  // unknown ID
      {},
  };
  for (const auto& b : bad) EXPECT_TRUE(h.silent(b));
  const auto& c = h.device().counters();
  EXPECT_EQ(c.truncated, 1U);
  EXPECT_EQ(c.oversized, 2U);
  EXPECT_EQ(c.bad_crc, 1U);
  EXPECT_EQ(c.bad_sync, 1U);
  EXPECT_EQ(c.direction_bit, 1U);
  EXPECT_EQ(c.unknown_id, 1U);
  const auto s = h.exchange(good);
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(decode_response(s[0].bytes, 22).value(), (Frame{3, 0xA2, {22}}));
}

TEST(GridScanExchange, FramesAreCutByIdleGap) {
  Rig h(Options{});
  boot(h);
  const Bytes good = request(2, CommandId::kInfoGetCountOfElements);
  // A frame in two chunks 200 µs apart (less than the 3.5-character gap) is one frame.
  h.send(Bytes(good.begin(), good.begin() + 4));
  h.run_for(200us);
  h.send(Bytes(good.begin() + 4, good.end()));
  h.run_for(40ms);
  ASSERT_EQ(h.take().size(), 1U);
  // Two halves 400 µs apart are two truncated frames.
  const Bytes next = request(4, CommandId::kInfoGetCountOfElements);
  h.send(Bytes(next.begin(), next.begin() + 4));
  h.run_for(400us);
  h.send(Bytes(next.begin() + 4, next.end()));
  h.run_for(40ms);
  EXPECT_TRUE(h.quiet());
  EXPECT_EQ(h.device().counters().truncated, 2U);
}

}  // namespace
}  // namespace rs4sim::gridscan::testing
