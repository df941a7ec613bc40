// Communication modes, test input, alignment and the blanking ↔ static configuration
// sequence ([GridScan manual §10.1, §10.4]) on the manual clock.
#include "tests/gridscan/gridscan_line.h"

namespace rs4sim::gridscan::testing {
namespace {

Frame decoded(const LineFrame& s, unsigned elements = 22) {
  auto f = decode_response(s.bytes, elements);
  EXPECT_TRUE(f) << f.error().message();
  return f ? f.value() : Frame{};
}

TEST(GridScanModes, FullStreamingEveryCycleOnItsOwnCounter) {
  Rig h(Options{});
  const auto ready = boot(h);
  // The answer (10 characters) and the stream message (15) both leave at the cycle end,
  // ready + 30 ms, one after the other: the window covers both on the wire.
  auto s = h.exchange(request(2, CommandId::kModeSetFullStreaming), 32ms);
  ASSERT_EQ(s.size(), 2U);  // the answer first, then the first streaming message
  EXPECT_EQ(decoded(s[0]), (Frame{3, 0x91, {}}));
  EXPECT_EQ(decoded(s[1]), (Frame{0, 0xB1, {0x16, 0x00, 0, 0, 0}}));  // stream SeqCnt 0
  EXPECT_EQ(s[0].start, ready + 30ms);
  EXPECT_EQ(s[1].start, ready + 30ms + chars(10));  // behind the answer on the line
  h.device().set_blocked(1);  // element 1
  h.run_for(30ms);
  s = h.take();
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(decoded(s[0]), (Frame{1, 0xB1, {0x16, 0x01, 0x01, 0, 0}}));
  EXPECT_EQ(s[0].start, ready + 60ms);
  // A request during streaming: answer, then the streaming message, same cycle end.
  s = h.exchange(request(4, CommandId::kModeGetCurrent), 30ms);
  ASSERT_EQ(s.size(), 2U);
  EXPECT_EQ(decoded(s[0]), (Frame{5, 0x94, {1}}));
  EXPECT_EQ(decoded(s[1]).seq, 2);
  s = h.exchange(request(6, CommandId::kModeSetPolling), 100ms);
  ASSERT_EQ(s.size(), 1U);  // streaming stopped
  EXPECT_EQ(decoded(s[0]), (Frame{7, 0x90, {}}));
}

TEST(GridScanModes, ReducedStreamingAndStandBy) {
  Rig h(Options{});
  boot(h);
  auto s = h.exchange(request(2, CommandId::kModeSetReducedStreaming), 65ms);
  ASSERT_EQ(s.size(), 3U);
  EXPECT_EQ(decoded(s[1]), (Frame{0, 0xB0, {0x16, 0x00}}));
  EXPECT_EQ(decoded(s[2]), (Frame{1, 0xB0, {0x16, 0x00}}));
  s = h.exchange(request(4, CommandId::kModeSetStandBy), 100ms);
  ASSERT_EQ(s.size(), 1U);        // stand-by stops streaming
  h.device().set_door_position(5);  // not scanning: the last known position stays
  s = h.exchange(request(6, CommandId::kDataFullState));
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(decoded(s[0]), (Frame{7, 0xB1, {0x16, 0x01, 0xFF, 0xFF, 0x3F}}));
  s = h.exchange(request(8, CommandId::kModeGetCurrent));
  EXPECT_EQ(decoded(s.at(0)).payload[0], 3);
}

TEST(GridScanModes, TestInputShowsAllInterruptedOnce) {
  Options o;
  o.elements = 12;
  Rig h(o);
  boot(h);
  auto s = h.exchange(request(2, CommandId::kSafetyTestInput));
  EXPECT_EQ(decoded(s.at(0), 12), (Frame{3, 0xC0, {}}));
  s = h.exchange(request(4, CommandId::kDataFullState));
  EXPECT_EQ(decoded(s.at(0), 12), (Frame{5, 0xB1, {12, 0x01, 0xFF, 0x0F}}));
  s = h.exchange(request(6, CommandId::kDataFullState));
  EXPECT_EQ(decoded(s.at(0), 12), (Frame{7, 0xB1, {12, 0x00, 0x00, 0x00}}));
}

TEST(GridScanModes, InfoCommands) {
  Options o;
  o.part_number = "116789";
  o.alignment_value = 0x0302;
  Rig h(o);
  boot(h);
  auto s = h.exchange(request(2, CommandId::kInfoGetProductInformation));
  EXPECT_EQ(decoded(s.at(0)), (Frame{3, 0xA1, {'1', '1', '6', '7', '8', '9', 0, 0, 0, 22}}));
  s = h.exchange(request(4, CommandId::kInfoGetVersion));
  EXPECT_EQ(decoded(s.at(0)).payload.size(), 10U);
  s = h.exchange(request(6, CommandId::kInfoGetAlignmentValue));
  EXPECT_EQ(decoded(s.at(0)), (Frame{7, 0xA4, {0x02, 0x03}}));
  s = h.exchange(request(8, CommandId::kInfoRequestAlignmentMode));
  EXPECT_EQ(decoded(s.at(0)), (Frame{9, 0xA5, {}}));
}

TEST(GridScanModes, AlignmentModeOnAnInterruptedPowerUp) {
  Options o;
  o.alignment_armed = true;
  o.blocked = 0b100;
  o.alignment_value = 700;
  Rig h(o);
  boot(h);
  EXPECT_TRUE(h.device().alignment_active());
  h.run_for(61ms);
  auto s = h.take();
  ASSERT_EQ(s.size(), 2U);
  EXPECT_EQ(decoded(s[0]), (Frame{0, 0xA4, {0xBC, 0x02}}));
  EXPECT_EQ(decoded(s[1]).seq, 1);
  h.device().set_blocked(0);  // free for the first time: alignment mode ends for good
  h.run_for(100ms);
  EXPECT_TRUE(h.quiet());
  h.device().set_blocked(0b100);
  h.device().power_off();
  h.device().power_on(h.now());
  h.run_for(1700ms);
  EXPECT_FALSE(h.device().alignment_active());
}

// [GridScan manual §10.4]: stand-by, allow, read, set → restart in the new mode.
TEST(GridScanConfig, ChangeToStaticRestartsTheCurtain) {
  Rig h(Options{});
  boot(h);
  auto s = h.exchange(request(2, CommandId::kConfigSetStatic));
  EXPECT_EQ(decoded(s.at(0)).payload[0], 4);  // not in stand-by
  s = h.exchange(request(4, CommandId::kConfigAllowChange));
  EXPECT_EQ(decoded(s.at(0)).payload[0], 1);  // not in stand-by
  s = h.exchange(request(6, CommandId::kModeSetStandBy));
  s = h.exchange(request(8, CommandId::kConfigSetStatic));
  EXPECT_EQ(decoded(s.at(0)).payload[0], 3);  // 0x50 missing
  s = h.exchange(request(10, CommandId::kConfigAllowChange));
  EXPECT_EQ(decoded(s.at(0)), (Frame{11, 0xD0, {0}}));
  s = h.exchange(request(12, CommandId::kConfigSetStatic));
  EXPECT_EQ(decoded(s.at(0)).payload[0], 2);  // 0x53 missing
  s = h.exchange(request(14, CommandId::kConfigGetCurrent));
  EXPECT_EQ(decoded(s.at(0)), (Frame{15, 0xD3, {0xAA}}));  // blanking
  const auto t = h.now();
  s = h.exchange(request(16, CommandId::kConfigSetStatic), 40ms);
  ASSERT_EQ(s.size(), 1U);  // no answer: the power-up version message
  EXPECT_EQ(decoded(s[0]).id, 0xA0);
  EXPECT_EQ(decoded(s[0]).seq, 0);
  EXPECT_LE(s[0].start, t + 30ms);
  EXPECT_EQ(h.device().configuration(), Configuration::kStatic);
  EXPECT_EQ(h.device().counters().restarts, 1U);
  EXPECT_EQ(h.device().leds(h.now()).rx_red, Led::kBlinkSlow);
  h.run_for(1700ms);
  s = h.take();
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(decoded(s[0]), (Frame{1, 0xB0, {0xFF, 0x00}}));  // static: door 255
  EXPECT_EQ(h.device().leds(h.now()).rx_green, Led::kBlink1Hz);
  h.run_for(120s);
  EXPECT_EQ(h.device().leds(h.now()).rx_green, Led::kOn);
}

TEST(GridScanConfig, The120sWindow) {
  Rig h(Options{});
  boot(h);  // power-up 1.7 s ago
  h.exchange(request(2, CommandId::kModeSetStandBy));
  h.run_for(118s);
  auto s = h.exchange(request(4, CommandId::kConfigAllowChange));  // ~119.8 s after power-up
  EXPECT_EQ(decoded(s.at(0)).payload[0], 0);
  s = h.exchange(request(6, CommandId::kConfigGetCurrent));
  h.run_for(1s);
  s = h.exchange(request(8, CommandId::kConfigSetBlanking));  // > 120 s
  EXPECT_EQ(decoded(s.at(0)), (Frame{9, 0xD2, {5}}));
  s = h.exchange(request(10, CommandId::kConfigAllowChange));
  EXPECT_EQ(decoded(s.at(0)).payload[0], 2);
}

}  // namespace
}  // namespace rs4sim::gridscan::testing
