// Fault injection for each of the controller's SIL 2 checks ([GridScan manual §10.2]) and
// the LEDs of an internal failure ([GridScan manual §13]).
#include "tests/gridscan/gridscan_line.h"

namespace rs4sim::gridscan::testing {
namespace {

const Bytes kClearState{0x43, 0x45, 0x44, 0x45, 0x03, 0xB0, 0x16, 0x00, 0xB0, 0x50, 0x3D, 0x98};

std::vector<LineFrame> reduced_state(Rig& h) {
  return h.exchange(request(2, CommandId::kDataReducedState));
}

TEST(GridScanFaults, NoneGivesTheKnownFrame) {
  Rig h(Options{});
  boot(h);
  const auto s = reduced_state(h);
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(s[0].bytes, kClearState);
}

TEST(GridScanFaults, LateAnswer) {
  Rig h(Options{});
  const auto ready = boot(h);
  h.device().set_faults({.transmit = {.late = 50ms}});
  const auto s = reduced_state(h);
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(s[0].bytes, kClearState);
  EXPECT_EQ(s[0].start, ready + 80ms);  // cycle end + 50 ms
}

TEST(GridScanFaults, WrongSeqCntDirectionBitBadCrc) {
  Rig h(Options{});
  boot(h);
  h.device().set_faults({.wrong_seq = true});
  auto s = reduced_state(h);
  EXPECT_EQ(decode_response(s.at(0).bytes, 22).value().seq, 4);
  h.device().set_faults({.direction_bit = true});
  s = h.exchange(request(4, CommandId::kDataReducedState));  // the device counted right
  EXPECT_EQ(decode_response(s.at(0).bytes, 22).error(), FrameError::kDirectionBit);
  h.device().set_faults({.bad_crc = true});
  s = h.exchange(request(6, CommandId::kDataReducedState));
  EXPECT_EQ(decode_response(s.at(0).bytes, 22).error(), FrameError::kBadCrc);
  h.device().set_faults({.transmit = {.silent = true}});
  EXPECT_TRUE(h.silent(request(8, CommandId::kDataReducedState)));
  h.device().set_faults({});
  s = h.exchange(request(10, CommandId::kDataReducedState));
  EXPECT_EQ(decode_response(s.at(0).bytes, 22).value().seq, 11);
}

TEST(GridScanFaults, InternalFailure) {
  Rig h(Options{});
  boot(h);
  h.device().set_internal_failure(true);
  const auto s = reduced_state(h);
  EXPECT_EQ(decode_response(s.at(0).bytes, 22).value().payload[1], 0x02);  // bit 9
  EXPECT_EQ(h.device().leds(h.now()).rx_red, Led::kBlinkFast);
}

TEST(GridScanFaults, ConfigNotSet) {
  Rig h(Options{});
  boot(h);
  h.device().set_faults({.config_not_set = true});
  h.exchange(request(2, CommandId::kModeSetStandBy));
  h.exchange(request(4, CommandId::kConfigAllowChange));
  h.exchange(request(6, CommandId::kConfigGetCurrent));
  const auto s = h.exchange(request(8, CommandId::kConfigSetStatic));
  EXPECT_EQ(decode_response(s.at(0).bytes, 22).value(), (Frame{9, 0xD1, {1}}));
}

TEST(GridScanFaults, PowerOffSilencesTheDevice) {
  Rig h(Options{});
  boot(h);
  h.device().power_off();
  EXPECT_TRUE(h.silent(request(2, CommandId::kDataReducedState)));
  EXPECT_EQ(h.device().leds(h.now()), Leds{});
  EXPECT_EQ(h.device().next_deadline(), std::nullopt);
}

// The sequence counter check detects "data repetition, incorrect sequence, loss or
// insertion" ([GridScan manual §10.2.2]). The expected frames are sealed by the manual's
// CRC rule (CRC-32/MPEG-2 over SeqCnt, ID and payload, little-endian), computed outside
// this code; the first is the power-up Reduced state of [GridScan manual §10.1.1].
TEST(GridScanFaults, RepetitionSendsEveryFrameTwice) {
  Rig h(Options{});
  const auto ready = boot(h);
  h.device().set_faults({.repeat_frames = true});
  const auto s = reduced_state(h);
  ASSERT_EQ(s.size(), 2U);
  EXPECT_EQ(s[0].bytes, kClearState);
  EXPECT_EQ(s[1].bytes, kClearState);  // the same SeqCnt 3 again
  // Both given out at the cycle end: on the line the copy follows the frame back to back.
  EXPECT_EQ(s[0].start, ready + 30ms);
  EXPECT_EQ(s[1].start, s[0].end);
  h.device().set_faults({});
  EXPECT_EQ(h.exchange(request(4, CommandId::kDataReducedState)).size(), 1U);
}

TEST(GridScanFaults, InsertionPutsTheStaleFrameFirstWithTheSameSeqCnt) {
  Rig h(Options{});
  boot(h);  // the last frame sent: the power-up Reduced state, SeqCnt 1
  h.device().set_faults({.insert_frames = true});
  auto s = h.exchange(request(2, CommandId::kModeGetCurrent));
  ASSERT_EQ(s.size(), 2U);
  // inserted: Reduced state (B0 16 00) sealed with the answer's SeqCnt 3
  EXPECT_EQ(s[0].bytes, kClearState);
  // the answer: Mode: Get current = 0, polling
  EXPECT_EQ(s[1].bytes, (Bytes{0x43, 0x45, 0x44, 0x45, 0x03, 0x94, 0x00, 0xAB, 0xEA, 0xF4, 0x62}));
  // (SeqCnt 2 again: the request channel's counter moved to 3, not 4)
  EXPECT_TRUE(h.silent(request(2, CommandId::kDataReducedState)));
  s = h.exchange(request(4, CommandId::kDataReducedState));
  ASSERT_EQ(s.size(), 2U);
  // inserted: the previous answer 94 00, now with SeqCnt 5; then the real Reduced state
  EXPECT_EQ(s[0].bytes, (Bytes{0x43, 0x45, 0x44, 0x45, 0x05, 0x94, 0x00, 0xB9, 0x01, 0x27, 0x66}));
  EXPECT_EQ(s[1].bytes,
            (Bytes{0x43, 0x45, 0x44, 0x45, 0x05, 0xB0, 0x16, 0x00, 0x6C, 0x34, 0xD2, 0x58}));
}

// Cat. 2: the controller's test must fail when the curtain does not test
// ([GridScan manual §10.1.2]: all elements interrupted for one scan, then the real state).
TEST(GridScanFaults, TestInputPassesAndFailsOnTheWire) {
  const Bytes test_answer{0x43, 0x45, 0x44, 0x45, 0x03, 0xC0, 0x37, 0xAB, 0xD6, 0x2F};
  const Bytes all_but_5{0x43, 0x45, 0x44, 0x45, 0x05, 0xB1, 0x16, 0x01, 0xEF,
                        0xFF, 0x3F, 0x2A, 0x95, 0x1A, 0x72};
  const Bytes clear_at_5{0x43, 0x45, 0x44, 0x45, 0x05, 0xB1, 0x16, 0x00, 0x00,
                         0x00, 0x00, 0x74, 0x2A, 0x13, 0xA6};
  const Bytes clear_at_7{0x43, 0x45, 0x44, 0x45, 0x07, 0xB1, 0x16, 0x00, 0x00,
                         0x00, 0x00, 0x56, 0xFA, 0xBD, 0x38};
  {  // element 5 stuck free: the test's scan shows every element but 5, then the real state
    Rig h(Options{});
    boot(h);
    h.device().set_faults({.stuck_free = 1U << 4});
    EXPECT_EQ(h.exchange(request(2, CommandId::kSafetyTestInput)).at(0).bytes, test_answer);
    EXPECT_EQ(h.exchange(request(4, CommandId::kDataFullState)).at(0).bytes, all_but_5);
    EXPECT_EQ(h.exchange(request(6, CommandId::kDataFullState)).at(0).bytes, clear_at_7);
  }
  {  // the test ignored: answered, and the next state is the real one at once
    Rig h(Options{});
    boot(h);
    h.device().set_faults({.test_ignored = true});
    EXPECT_EQ(h.exchange(request(2, CommandId::kSafetyTestInput)).at(0).bytes, test_answer);
    EXPECT_EQ(h.exchange(request(4, CommandId::kDataFullState)).at(0).bytes, clear_at_5);
  }
  {  // no fault: every element interrupted, bit 8 set, in the one message after the test
    Rig h(Options{});
    boot(h);
    h.exchange(request(2, CommandId::kSafetyTestInput));
    const auto f = decode_response(h.exchange(request(4, CommandId::kDataFullState)).at(0).bytes, 22);
    EXPECT_EQ(f.value().payload, (Payload{0x16, 0x01, 0xFF, 0xFF, 0x3F}));
    EXPECT_EQ(h.exchange(request(6, CommandId::kDataFullState)).at(0).bytes, clear_at_7);
  }
}

// A stuck element reads free with an object in front of it: bit 8 and the bitmap lose it
// (the manual's Full state frame with elements 1 and 22 interrupted, light soiling, minus 22).
TEST(GridScanFaults, AnElementStuckFreeHidesItsObject) {
  Options o;
  o.blocked = 1U | (1U << 21);
  o.soiling = 1;
  Rig h(o);
  boot(h);
  h.device().set_faults({.stuck_free = 1U << 21});
  EXPECT_EQ(h.exchange(request(2, CommandId::kDataFullState)).at(0).bytes,
            (Bytes{0x43, 0x45, 0x44, 0x45, 0x03, 0xB1, 0x16, 0x41, 0x01, 0x00, 0x00, 0xC0, 0xE1,
                   0x87, 0x0D}));
  h.device().set_faults({.stuck_free = 1U | (1U << 21)});
  EXPECT_FALSE(h.device().current_report().interrupted);  // nothing seen, bit 8 clear
  h.device().set_faults({});  // element 22 sees its object again
  EXPECT_EQ(h.exchange(request(4, CommandId::kDataFullState)).at(0).bytes,
            (Bytes{0x43, 0x45, 0x44, 0x45, 0x05, 0xB1, 0x16, 0x41, 0x01, 0x00, 0x20, 0xF1, 0x3A,
                   0x96, 0x32}));
}

// [GridScan manual §10.1.1]: a failed activation leaves the curtain in polling mode.
TEST(GridScanFaults, AFailedModeActivationFallsBackToPolling) {
  const Bytes set_answer{0x43, 0x45, 0x44, 0x45, 0x03, 0x91, 0x87, 0x1D, 0x80, 0x53};
  for (const bool fails : {false, true}) {
    SCOPED_TRACE(fails ? "activation fails" : "activation works");
    Rig h(Options{});
    boot(h);
    h.device().set_faults({.mode_activation_fails = fails});
    EXPECT_TRUE(h.silent(request(2, CommandId::kModeSetFullStreaming), 0ms));
    h.run_for(100ms);  // three cycles of 30 ms: the answer, then a stream or nothing
    const auto sent = h.take();
    ASSERT_FALSE(sent.empty());
    EXPECT_EQ(sent[0].bytes, set_answer);
    // streaming: the Full state on its own SeqCnt from 0, every cycle
    EXPECT_EQ(sent.size(), fails ? 1U : 4U);  // cycle ends at +30, +60, +90 ms
    if (!fails) {
      EXPECT_EQ(sent[1].bytes, (Bytes{0x43, 0x45, 0x44, 0x45, 0x00, 0xB1, 0x16, 0x00, 0x00,
                                      0x00, 0x00, 0x96, 0xFF, 0xD8, 0xD0}));
    }
    const auto s = h.exchange(request(4, CommandId::kModeGetCurrent), 30ms);
    ASSERT_FALSE(s.empty());
    EXPECT_EQ(s[0].bytes, fails ? (Bytes{0x43, 0x45, 0x44, 0x45, 0x05, 0x94, 0x00, 0xB9, 0x01, 0x27,
                                         0x66})
                                : (Bytes{0x43, 0x45, 0x44, 0x45, 0x05, 0x94, 0x01, 0x0E, 0x1C, 0xE6,
                                         0x62}));
    EXPECT_EQ(h.device().counters().mode_fallbacks, fails ? 1U : 0U);
  }
}

}  // namespace
}  // namespace rs4sim::gridscan::testing
