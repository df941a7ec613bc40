// RS232 framing of the RS4 ([roboticslibrary/rl LeuzeRs4.cpp]): every worked example of the framing
// rules as a known answer, framed and deframed, byte for byte.
#include "rs4/protocol/rs232.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace rs4sim::rs4::protocol {
namespace {

using Bytes = std::vector<std::uint8_t>;

struct Example {
  const char* name;
  Bytes body;  // CMD, options, [password], data: unstuffed, without CHK
  Bytes wire;  // the expected frame
};

const std::vector<Example>& examples() {
  static const std::vector<Example> kExamples{
      {"alive, no ack",
       {0x14, 0x01},
       {0x00, 0x00,          // start mark
        0x14,                // CMD COM_CMD_ALIVE
        0x01,                // OPT1: one option byte
        0x15,                // CHK = 14 ^ 01
        0x00, 0x00, 0x00}},  // end mark
      {"set baud 4800",
       {0x19, 0x41, 0x00, 0x00},
       {0x00, 0x00,          // start mark
        0x19,                // CMD set baud rate
        0x41,                // OPT1: ack requested, one option byte
        0x00, 0x00,          // data 00 00 (4800 baud)
        0xFF,                // stuffed after two zeros, counted in the check
        0xA7,                // CHK = 19 ^ 41 ^ 00 ^ 00 ^ FF
        0x00, 0x00, 0x00}},  // end mark
      {"password frame",
       {0x10, 0x21, 0x52, 0x4F, 0x44, 0x34, 0x4C, 0x45, 0xFF, 0xFF},
       {0x00, 0x00,                          // start mark
        0x10,                                // CMD
        0x21,                                // OPT1: password follows
        0x52, 0x4F, 0x44, 0x34, 0x4C, 0x45,  // "ROD4LE"
        0xFF, 0xFF,                          // password padding
        0x55,                                // CHK
        0x00, 0x00, 0x00}},                  // end mark
      {"request one scan",
       {0x24, 0x01},
       {0x00, 0x00, 0x24, 0x01, 0x25, 0x00, 0x00, 0x00}},  // start, CMD, OPT1, CHK, end
      {"measurement",
       {0x23, 0x0B, 0x80, 0x81, 0x00, 0xFE, 0x00, 0xFE, 0x00, 0xFE, 0x01, 0xFE,
        0x04, 0x00, 0x00, 0x00, 0x08, 0x03, 0xE8, 0x00, 0x00, 0x01, 0x00},
       {0x00, 0x00,                                      // start mark
        0x23, 0x0B, 0x80, 0x81,                          // CMD 0x23, OPT1 0B, OPT2 80, OPT3 81
        0x00, 0xFE, 0x00, 0xFE, 0x00, 0xFE, 0x01, 0xFE,  // scan number 1 with fillers
        0x04,                                            // resolution 4
        0x00, 0x00, 0xFF,                                // start 0 + stuffed FF
        0x00, 0x08,                                      // stop 8
        0x03, 0xE8,                                      // 1000 mm
        0x00, 0x00, 0xFF,                                // 0 mm + stuffed FF
        0x01, 0x00,                                      // 256 mm
        0xCE,                                            // CHK
        0x00, 0x00, 0x00}},                              // end mark
  };
  return kExamples;
}

TEST(Rs4Rs232, FramerMatchesEveryWorkedExample) {
  for (const auto& ex : examples()) {
    auto framed = frame_rs232(ex.body);
    ASSERT_TRUE(framed) << ex.name;
    EXPECT_EQ(framed.value(), ex.wire) << ex.name;
  }
}

TEST(Rs4Rs232, DeframerMatchesEveryWorkedExample) {
  for (const auto& ex : examples()) {
    Rs232Deframer d;
    auto events = d.feed(ex.wire);
    ASSERT_EQ(events.size(), 1U) << ex.name;
    ASSERT_TRUE(events[0]) << ex.name << ": " << events[0].error().message();
    EXPECT_EQ(events[0].value(), ex.body) << ex.name;
    EXPECT_EQ(d.counters().frames, 1U);
  }
}

TEST(Rs4Rs232, DeframerTakesOneByteAtATimeAndBackToBackFrames) {
  Bytes stream;
  for (const auto& ex : examples()) stream.insert(stream.end(), ex.wire.begin(), ex.wire.end());
  Rs232Deframer d;
  std::vector<Rs232Deframer::Event> events;
  for (const auto byte : stream) d.feed(std::span(&byte, 1), events);
  ASSERT_EQ(events.size(), examples().size());
  for (std::size_t i = 0; i < events.size(); ++i) {
    ASSERT_TRUE(events[i]);
    EXPECT_EQ(events[i].value(), examples()[i].body);
  }
}

TEST(Rs4Rs232, EverySplitPointGivesTheSameFrames) {
  Bytes stream;
  for (const auto& ex : examples()) stream.insert(stream.end(), ex.wire.begin(), ex.wire.end());
  for (std::size_t cut = 0; cut <= stream.size(); ++cut) {
    Rs232Deframer d;
    std::vector<Rs232Deframer::Event> events;
    d.feed(std::span(stream).first(cut), events);
    d.feed(std::span(stream).subspan(cut), events);
    ASSERT_EQ(events.size(), examples().size()) << "cut at " << cut;
    for (std::size_t i = 0; i < events.size(); ++i) {
      ASSERT_TRUE(events[i]) << "cut at " << cut;
      EXPECT_EQ(events[i].value(), examples()[i].body) << "cut at " << cut;
    }
  }
}

// `stream` gives `d` one frame, `body`.
void expect_one_frame(Rs232Deframer& d, const Bytes& stream, const Bytes& body) {
  auto events = d.feed(stream);
  ASSERT_EQ(events.size(), 1U);
  ASSERT_TRUE(events[0]);
  EXPECT_EQ(events[0].value(), body);
}

// `stream` gives `d` a broken frame with `error`, then the frame `body`.
void expect_error_then_frame(Rs232Deframer& d, const Bytes& stream, ProtocolError error,
                             const Bytes& body) {
  auto events = d.feed(stream);
  ASSERT_EQ(events.size(), 2U);
  ASSERT_FALSE(events[0]);
  EXPECT_EQ(events[0].error(), error);
  ASSERT_TRUE(events[1]);
  EXPECT_EQ(events[1].value(), body);
}

// `body` frames to the known answer `wire`, and `wire` deframes to `body` alone.
void expect_framing(const Bytes& body, const Bytes& wire) {
  auto framed = frame_rs232(body);
  ASSERT_TRUE(framed);
  EXPECT_EQ(framed.value(), wire);
  Rs232Deframer d;
  expect_one_frame(d, wire, body);
}

TEST(Rs4Rs232, BodyEndingInOneZero) {
  // body 23 01 00: no stuffing, CHK = 23 ^ 01 ^ 00 = 22, then the end mark
  const Bytes wire{0x00, 0x00, 0x23, 0x01, 0x00, 0x22, 0x00, 0x00, 0x00};
  expect_framing(Bytes{0x23, 0x01, 0x00}, wire);
}

TEST(Rs4Rs232, StuffedZerosFollowedByARealFF) {
  // body 31 01 00 00 FF: 00 00 → stuff FF, then the body's own FF
  const Bytes wire{0x00, 0x00, 0x31, 0x01, 0x00, 0x00,
                   0xFF,  // stuffed
                   0xFF,  // data byte 0xFF
                   0x30,  // CHK = 31 ^ 01 ^ FF ^ FF
                   0x00, 0x00, 0x00};
  expect_framing(Bytes{0x31, 0x01, 0x00, 0x00, 0xFF}, wire);
}

TEST(Rs4Rs232, CheckZeroIsSentAsFF) {
  // 0x12 ^ 0x12 = 0x00 → CHK 0xFF
  expect_framing(Bytes{0x12, 0x12}, Bytes{0x00, 0x00, 0x12, 0x12, 0xFF, 0x00, 0x00, 0x00});
}

TEST(Rs4Rs232, FourZerosStuffTwice) {
  // body 01 01 00 00 00 00: 00 00 FF 00 00 FF ([roboticslibrary/rl LeuzeRs4.cpp] "00 00 FF 00 00 FF
  // is legal")
  expect_framing(Bytes{0x01, 0x01, 0x00, 0x00, 0x00, 0x00},
                 Bytes{0x00, 0x00, 0x01, 0x01, 0x00, 0x00, 0xFF, 0x00, 0x00, 0xFF,
                       0xFF,  // CHK: 01^01^FF^FF = 00 → FF
                       0x00, 0x00, 0x00});
}

TEST(Rs4Rs232, FramerRejectsBadCommandAndEmpty) {
  EXPECT_EQ(frame_rs232(Bytes{}).error(), ProtocolError::kEmptyFrame);
  EXPECT_EQ(frame_rs232(Bytes{0x00, 0x01}).error(), ProtocolError::kBadCommandByte);
  EXPECT_EQ(frame_rs232(Bytes{0xFF, 0x01}).error(), ProtocolError::kBadCommandByte);
}

TEST(Rs4Rs232, BadCheckIsReportedAndNextFrameIsFound) {
  Bytes stream{0x00, 0x00, 0x14, 0x01, 0x16, 0x00, 0x00, 0x00};  // CHK 16 instead of 15
  const auto& good = examples()[3].wire;                         // request one scan
  stream.insert(stream.end(), good.begin(), good.end());
  Rs232Deframer d;
  expect_error_then_frame(d, stream, ProtocolError::kBadCheck, Bytes{0x24, 0x01});
  EXPECT_EQ(d.counters().check_errors, 1U);
  EXPECT_EQ(d.counters().frames, 1U);
}

// `prefix`, then the first example's frame (the alive telegram 14 01).
Bytes then_alive(Bytes prefix) {
  const auto& good = examples()[0].wire;
  prefix.insert(prefix.end(), good.begin(), good.end());
  return prefix;
}

TEST(Rs4Rs232, GarbageBeforeAFrameIsSkipped) {
  // Noise (a single zero is no start mark), then the alive frame.
  const Bytes stream = then_alive({0x55, 0xAA, 0x13, 0x00, 0x77});
  Rs232Deframer d;
  expect_one_frame(d, stream, Bytes{0x14, 0x01});
  EXPECT_EQ(d.counters().garbage_bytes, 4U);
}

TEST(Rs4Rs232, CutOffFrameIsAStuffingViolationAndTheNextFrameSurvives) {
  // A frame cut after 14 01, then a complete alive frame: "00 00 14" inside a frame.
  const Bytes stream = then_alive({0x00, 0x00, 0x14, 0x01});
  Rs232Deframer d;
  expect_error_then_frame(d, stream, ProtocolError::kStuffingViolation, Bytes{0x14, 0x01});
  EXPECT_EQ(d.counters().stuffing_errors, 1U);
}

TEST(Rs4Rs232, TooShortFrame) {
  Rs232Deframer d;
  auto events = d.feed(Bytes{0x00, 0x00, 0x14, 0x14, 0x00, 0x00, 0x00});  // CMD + CHK only
  ASSERT_EQ(events.size(), 1U);
  ASSERT_FALSE(events[0]);
  EXPECT_EQ(events[0].error(), ProtocolError::kFrameTooShort);
  EXPECT_EQ(d.counters().short_frames, 1U);
}

TEST(Rs4Rs232, TooLongFrameIsBoundedAndResyncs) {
  Rs232Deframer d(8);
  Bytes stream{0x00, 0x00, 0x23};
  stream.insert(stream.end(), 20, 0x11);
  stream.insert(stream.end(), {0x00, 0x00, 0x00});
  expect_error_then_frame(d, then_alive(stream), ProtocolError::kFrameTooLong, Bytes{0x14, 0x01});
  EXPECT_EQ(d.counters().long_frames, 1U);
}

TEST(Rs4Rs232, StuffedFFOutsideAFrameIsNoStart) {
  // Joining mid-frame at "00 00 FF": 0xFF is never a command byte.
  const Bytes stream = then_alive({0x00, 0x00, 0xFF, 0x31});
  Rs232Deframer d;
  expect_one_frame(d, stream, Bytes{0x14, 0x01});
  EXPECT_EQ(d.counters().bad_command_bytes, 1U);
  EXPECT_EQ(d.counters().garbage_bytes, 2U);
}

}  // namespace
}  // namespace rs4sim::rs4::protocol
