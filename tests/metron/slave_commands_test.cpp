// Slave line mode, no node: every command's correct operation as annotated bytes
// [METRON manual "No node"]. Byte values are the project's EXTENSION (metron/wire_table.h):
// start 0x02, commands 0x01..0x0D in the manual's order, reply code = command code.
#include "metron/mode_spec.h"
#include "tests/metron/metron_line.h"

#include <gtest/gtest.h>

namespace rs4sim::metron::testing {
namespace {

using namespace std::chrono_literals;

TEST(MetronSlave, RequestOssdStatus) {
  Rig rig(slave_options());
  EXPECT_EQ(only_reply(rig, {0x02,    // frame start
                            0x01,    // length: command only
                            0x0C,    // #12 Request OSSD status
                            0xF3}),  // checksum ~0x0C
            (Bytes{0x02, 0x03,       // start, length 3
                   0x0C,             // reply code = command
                   0x01, 0x01,       // OSSD1 ON, OSSD2 ON (free curtain)
                   0xF1}));          // ~(0x0C+1+1)
  rig.device().set_beam(3, true);
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x0C, 0xF3}),
            (Bytes{0x02, 0x03, 0x0C, 0x00, 0x00, 0xF3}));  // both OFF
}

TEST(MetronSlave, RequestActiveBeamStatusAllBeams24) {
  Rig rig(slave_options());
  const std::uint16_t blocked[] = {9, 10, 11, 12, 13};
  rig.device().set_interrupted(blocked);
  EXPECT_EQ(only_reply(rig, {0x02, 0x02, 0x09,  // start, length 2, #9
                            0x00,              // all beams (EXTENSION)
                            0xF6}),
            (Bytes{0x02, 0x04, 0x09,
                   0x00,  // beams 1..8
                   0x1F,  // beams 9..13 in bits 0..4 (beam 9 = bit 0, LSB first)
                   0x00,  // beams 17..24
                   0xD7}));
}

TEST(MetronSlave, RequestActiveBeamStatusAllBeams30UsesFourBytes) {
  auto o = slave_options();
  o.beams = 30;
  Rig rig(o);
  const std::uint16_t blocked[] = {25, 26, 27, 28, 29, 30};
  rig.device().set_interrupted(blocked);
  // "a 30-beam light curtain will send 4 bytes, the last two bits as X" (sent as 0)
  EXPECT_EQ(only_reply(rig, {0x02, 0x02, 0x09, 0x00, 0xF6}),
            (Bytes{0x02, 0x05, 0x09, 0x00, 0x00, 0x00, 0x3F, 0xB7}));
}

TEST(MetronSlave, RequestActiveBeamStatusOneBeam) {
  Rig rig(slave_options());
  rig.device().set_beam(10, true);
  EXPECT_EQ(only_reply(rig, {0x02, 0x02, 0x09, 0x0A /* beam 10 */, 0xEC}),
            (Bytes{0x02, 0x02, 0x09, 0x01 /* interrupted */, 0xF5}));
}

TEST(MetronSlave, RequestInstantaneousMeasurements) {
  Rig rig(slave_options());
  const std::uint16_t blocked[] = {9, 10, 11, 12, 13};
  rig.device().set_interrupted(blocked);
  EXPECT_EQ(only_reply(rig, {0x02, 0x04, 0x0A,  // #10, three fields
                            0x01, 0x02, 0x03,  // first, last, count
                            0xEF}),
            (Bytes{0x02, 0x04, 0x0A, 0x09, 0x0D, 0x05,  // 9, 13, 5
                   0xDA}));
}

TEST(MetronSlave, RequestConfiguration) {
  Rig rig(slave_options());
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x0B, 0xF4}), (Bytes{0x02, 0x06, 0x0B,
                                                             0x18,  // 24 beams
                                                             0x00,  // input type: no function
                                                             0x00,  // node: none
                                                             0x0A,  // scan cycle 10 ms
                                                             0x14,  // t_response 20 ms
                                                             0xBE}));
}

TEST(MetronSlave, RequestLightCurtainStatus) {
  Rig rig(slave_options());
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x0D, 0xF2}),
            (Bytes{0x02, 0x02, 0x0D, 0x03 /* synchronised, OSSD enabled */, 0xEF}));
}

TEST(MetronSlave, OssdFunctionCommands) {
  Rig rig(slave_options());
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x03, 0xFC}), (Bytes{0x02, 0x01, 0x03, 0xFC}));
  EXPECT_EQ(rig.device().slave_state().ossd, OssdFunction::kDisabled);
  EXPECT_FALSE(rig.device().ossd_on());
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x02, 0xFD}), (Bytes{0x02, 0x01, 0x02, 0xFD}));
  EXPECT_TRUE(rig.device().ossd_on());
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x04, 0xFB}), (Bytes{0x02, 0x01, 0x04, 0xFB}));
  EXPECT_EQ(rig.device().slave_state().ossd, OssdFunction::kStandby);
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x02, 0xFD}), (Bytes{0x02, 0x01, 0x02, 0xFD}));
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x05, 0xFA}), (Bytes{0x02, 0x01, 0x05, 0xFA}));
  EXPECT_TRUE(rig.device().slave_state().ossd_measuring);
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x06, 0xF9}), (Bytes{0x02, 0x01, 0x06, 0xF9}));
  EXPECT_FALSE(rig.device().slave_state().ossd_measuring);
}

TEST(MetronSlave, StartStopMeasurementReturnsTheMaximum) {
  Rig rig(slave_options());
  rig.device().set_beam(3, true);
  EXPECT_EQ(only_reply(rig, {0x02, 0x02, 0x07, 0x01 /* first interrupted */, 0xF7}),
            (Bytes{0x02, 0x01, 0x07, 0xF8}));
  rig.device().set_beam(9, true);
  rig.device().set_beam(3, false);  // first = 9: the maximum
  rig.device().set_beam(4, true);   // first = 4
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x08, 0xF7}),
            (Bytes{0x02, 0x02, 0x08, 0x09 /* maximum */, 0xEE}));
}

// The replies of #8, #9, #11 and #13 follow the wire table (EXTENSION, docs/metron.md#replies):
// the same requests as above, with a table that changes what they return. Checksums by hand:
// the one's complement of code + data (the default layout).
TEST(MetronSlaveReplies, FollowTheWireTable) {
  auto o = slave_options();
  o.wire.replies.stop_measurement = {StopItem::kCode, StopItem::kMaximum};
  o.wire.replies.beam_interrupted = 0xAA;
  o.wire.replies.beam_free = 0x55;
  o.wire.replies.configuration = {ConfigItem::kTResponse, ConfigItem::kBeams};
  o.wire.replies.curtain_status = {0x80, 0x00, 0x00, 0x00, 0x00, 0x01, 0x00};
  Rig rig(o);
  rig.device().set_beam(10, true);
  EXPECT_EQ(only_reply(rig, {0x02, 0x02, 0x09, 0x0A /* beam 10 */, 0xEC}),
            (Bytes{0x02, 0x02, 0x09, 0xAA /* interrupted, the table's */, 0x4C}));
  EXPECT_EQ(only_reply(rig, {0x02, 0x02, 0x09, 0x0B /* beam 11 */, 0xEB}),
            (Bytes{0x02, 0x02, 0x09, 0x55 /* free */, 0xA1}));
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x0B, 0xF4}),
            (Bytes{0x02, 0x03, 0x0B,
                   0x14,  // t_response 20 ms
                   0x18,  // 24 beams
                   0xC8}));
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x0D, 0xF2}),
            (Bytes{0x02, 0x02, 0x0D, 0x81 /* synchronised 0x80, interrupted 0x01 */, 0x71}));
  EXPECT_EQ(only_reply(rig, {0x02, 0x02, 0x07, 0x01 /* first interrupted */, 0xF7}),
            (Bytes{0x02, 0x01, 0x07, 0xF8}));
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x08, 0xF7}),
            (Bytes{0x02, 0x03, 0x08,
                   0x01,  // the measurement's code: first interrupted
                   0x0A,  // its maximum: beam 10
                   0xEC}));
}

TEST(MetronSlave, ResetSoftwareNeverReplies) {
  Rig rig(slave_options());
  rig.send({0x02, 0x01, 0x03, 0xFC});  // disable OSSD
  rig.run_for(100ms);
  EXPECT_TRUE(rig.silent({0x02, 0x01, 0x01, 0xFE}));  // #1 Reset software
  EXPECT_EQ(rig.device().counters().resets, 1U);
  EXPECT_EQ(rig.device().slave_state().ossd, OssdFunction::kEnabled);  // state restarted
  // deaf while restarting (reset_time 500 ms from the reset)
  EXPECT_TRUE(rig.silent({0x02, 0x01, 0x0C, 0xF3}));
  EXPECT_EQ(rig.device().counters().ignored_in_reset, 4U);
  rig.run_for(400ms);
  EXPECT_EQ(rig.exchange({0x02, 0x01, 0x0C, 0xF3}).size(), 1U);
}

// The reply to the message sent at `t0` goes out at `t0 + late`, not a nanosecond earlier.
void expect_reply_at(Rig& rig, stream::TimePoint t0, stream::Duration late) {
  rig.run_to(t0 + late - 1ns);
  EXPECT_FALSE(rig.on_the_wire()) << "not given out yet";
  rig.run_to(t0 + late);
  EXPECT_TRUE(rig.on_the_wire()) << "given out now";
}

// One reply by `t0 + 20ms`, started at `start`.
void expect_one_reply_started(Rig& rig, stream::TimePoint t0, stream::TimePoint start) {
  rig.run_to(t0 + 20ms);
  const auto s = rig.take();
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(s[0].start, start);
}

TEST(MetronSlave, ReplyTimingIsEquation3) {
  // t_late = n_byte * 11 * 0.05208 ms + t_response / 2 from the start of the host's message
  // [METRON manual "Slave line mode"]: 4 bytes -> 44 bits / 19200 = 2.291667 ms, + 10 ms.
  Rig rig(slave_options());
  const auto t0 = rig.now();
  rig.send({0x02, 0x01, 0x0C, 0xF3});
  expect_reply_at(rig, t0, 12'291'667ns);  // its 6 characters take 3.44 ms
  expect_one_reply_started(rig, t0, t0 + 12'291'667ns);
}

// The same with t_response 40 ms set by --mode slave,t-response=40: 2.291667 ms + 20 ms.
TEST(MetronSlave, ReplyTimingFollowsTheUsersTResponse) {
  auto o = slave_options();
  ASSERT_EQ(apply_mode_spec("slave,t-response=40", o), "");
  Rig rig(o);
  const auto t0 = rig.now();
  rig.send({0x02, 0x01, 0x0C, 0xF3});
  expect_reply_at(rig, t0, 22'291'667ns);
}

TEST(MetronSlave, ReplyTimingCountsFromTheFirstByte) {
  Rig rig(slave_options());
  const auto t0 = rig.now();
  rig.send({0x02, 0x01});
  rig.run_for(1ms);
  rig.send({0x0C, 0xF3});
  expect_one_reply_started(rig, t0, t0 + 12'291'667ns);
}

TEST(MetronSlave, LineIs19200_8E1) {
  EXPECT_EQ(line_asked_for_9600_8n1(slave_options()),
            (stream::LineSettings{19200, 8, stream::Parity::kEven, 1}));
}

}  // namespace
}  // namespace rs4sim::metron::testing
