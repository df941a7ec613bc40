// A changed wire table changes the bytes on the wire, both ways: command codes, frame start,
// measurement codes, the all-beams selector and bit order, the standard-mode characters, and
// the reply and report layouts (metron/wire_table.h, EXTENSION [docs/metron.md#wire-table]).
// Each exchange runs over the shared line rig (tests/metron/metron_line.h) at 19200 8E1 (11
// bit times a character) on the manual clock; the expected bytes are written out by hand,
// one field per line, with the checksums summed by hand (~(sum mod 256)).
#include "tests/metron/metron_line.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>

namespace rs4sim::metron {
namespace {

using namespace std::chrono_literals;
using testing::Bytes;
using testing::only_reply;
using testing::Rig;
using RF = ReplyField;

// Equation 3 for a 4-byte request with t_response 20 ms: 44 bit times at 19200 baud
// (2.291667 ms, rounded up to the ns) + 10 ms [METRON manual "Slave line mode"].
constexpr auto kReplyAfter4 = 2'291'667ns + 10ms;

Options swapped_and_reordered() {
  Options o;
  // #12 Request OSSD status and #13 Request light curtain status swap their codes.
  o.wire.commands[static_cast<std::size_t>(Command::kRequestOssdStatus)] = 0x0D;
  o.wire.commands[static_cast<std::size_t>(Command::kRequestCurtainStatus)] = 0x0C;
  // Reply: start | code | Length (data only) | data | checksum over Length, code and data.
  o.wire.reply.fields = {RF::kStart, RF::kCode, RF::kLength, RF::kData, RF::kChecksum};
  o.wire.reply.length_counts = field_bit(RF::kData);
  o.wire.reply.checksum_covers = field_bit(RF::kLength) | field_bit(RF::kCode) | field_bit(RF::kData);
  return o;
}

TEST(MetronWireLayout, SwappedCommandsAndAReorderedReply) {
  auto o = swapped_and_reordered();
  ASSERT_EQ(o.validate(), "");
  Rig rig(o);
  // 0x0D is now Request OSSD status (the default table's light curtain status).
  const stream::TimePoint sent = rig.now();  // send(): the request is at the device now
  const auto got = rig.exchange({0x02,    // frame start
                                 0x01,    // Length: command only
                                 0x0D,    // #12 Request OSSD status (swapped)
                                 0xF2});  // ~0x0D
  ASSERT_EQ(got.size(), 1U);
  EXPECT_EQ(got[0].bytes, (Bytes{0x02,     // frame start
                                 0x0D,     // reply code: the command's code
                                 0x02,     // Length: the 2 data bytes only
                                 0x01,     // OSSD1 ON (free, synchronised, enabled)
                                 0x01,     // OSSD2 ON
                                 0xEE}));  // ~(02 + 0D + 01 + 01)
  // Equation 3 times the reply's first bit (LineFrame.start, when the device gave it out),
  // not its end 6 characters later.
  EXPECT_EQ(got[0].start - sent, kReplyAfter4);
  // 0x0C is now Request light curtain status.
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x0C, 0xF3}),
            (Bytes{0x02,     // frame start
                   0x0C,     // #13 (swapped)
                   0x01,     // Length: 1 data byte
                   0x03,     // synchronised | OSSD enabled
                   0xEF}));  // ~(01 + 0C + 03)
  // An error answer in the same layout: no data, Length 0.
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x0D, 0x00}),  // checksum wrong
            (Bytes{0x02,     // frame start
                   0xE1,     // E1
                   0x00,     // Length: no data
                   0x1E}));  // ~(00 + E1)
}

TEST(MetronWireLayout, NodeReplyWithoutStartAndLength) {
  Options o;
  o.node_enabled = true;
  o.node = 5;
  o.wire.reply.fields = {RF::kNode, RF::kCode, RF::kData, RF::kChecksum};
  o.wire.reply.length_counts = 0;
  o.wire.reply.checksum_covers = field_bit(RF::kNode) | field_bit(RF::kCode) | field_bit(RF::kData);
  ASSERT_EQ(o.validate(), "");
  Rig rig(o);
  EXPECT_EQ(only_reply(rig, {0x02, 0x05, 0x01, 0x0C, 0xF3}),  // node 5, #12
            (Bytes{0x05,     // node
                   0x0C,     // #12 Request OSSD status
                   0x01,     // OSSD1 ON
                   0x01,     // OSSD2 ON
                   0xEC}));  // ~(05 + 0C + 01 + 01)
}

TEST(MetronWireLayout, BadChecksumFaultFindsTheChecksumWhereTheLayoutPutsIt) {
  Options o;
  o.wire.reply.fields = {RF::kStart, RF::kLength, RF::kChecksum, RF::kCode, RF::kData};
  Rig rig(o);
  Faults f;
  f.bad_checksum = true;
  rig.device().set_faults(f);
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x0C, 0xF3}),
            (Bytes{0x02,     // frame start
                   0x03,     // Length: code + 2 data
                   0x0E,     // ~F1: the checksum ~(0C + 01 + 01) inverted
                   0x0C,     // #12
                   0x01,     // OSSD1 ON
                   0x01}));  // OSSD2 ON
}

TEST(MetronWireLayout, FrameStartMeasurementCodesAndBeamBits) {
  Options o;
  o.wire.frame_start = 0x7E;
  o.wire.measurements[static_cast<std::size_t>(Measurement::kFirstInterrupted)] = 0x10;
  o.wire.all_beams = 0xFF;
  o.wire.beam_bits_lsb_first = false;
  ASSERT_EQ(o.validate(), "");
  Rig rig(o);
  const std::uint16_t beams[] = {9, 10, 11, 12, 13};
  ASSERT_FALSE(rig.device().set_interrupted(beams));
  // The default frame start is line noise now: nothing arrives and nothing is on the wire.
  EXPECT_TRUE(rig.silent({0x02, 0x01, 0x0C, 0xF3}));
  EXPECT_EQ(rig.device().counters().noise_bytes, 4U);
  EXPECT_EQ(only_reply(rig, {0x7E,    // frame start
                            0x02,    // Length
                            0x09,    // #9 Request active beam status
                            0xFF,    // all beams (the table's selector)
                            0xF7}),  // ~(09 + FF)
            (Bytes{0x7E,     // frame start
                   0x04,     // Length: code + 3 data
                   0x09,     // #9
                   0x00,     // beams 1..8 free
                   0xF8,     // beams 9..13 in bits 7..3 (MSB first)
                   0x00,     // beams 17..24 free
                   0xFE}));  // ~(09 + 00 + F8 + 00)
  EXPECT_EQ(only_reply(rig, {0x7E, 0x02, 0x0A,
                            0x10,    // "first interrupted beam" under its new code
                            0xE5}),  // ~(0A + 10)
            (Bytes{0x7E, 0x02, 0x0A,
                   0x09,     // beam 9
                   0xEC}));  // ~(0A + 09)
  // The old code 0x01 is no measurement any more: E2.
  EXPECT_EQ(only_reply(rig, {0x7E, 0x02, 0x0A, 0x01, 0xF4}), (Bytes{0x7E, 0x01, 0xE2, 0x1D}));
}

TEST(MetronWireLayout, ReportCharactersAndOrder) {
  Options o;
  o.line_mode = LineMode::kStandard;
  o.reporting_mode = ReportingMode::kOnRequest;
  o.format = Format::kHex;
  o.checksum = true;
  o.wire.report_start = '[';
  o.wire.report_end = ']';
  o.wire.request_char = '!';
  o.wire.report.order = {ReportField::kStart, ReportField::kChecksum, ReportField::kData,
                         ReportField::kEnd};
  o.wire.report.checksum_over_characters = true;
  ASSERT_EQ(o.validate(), "");
  Rig rig(o);
  const std::uint16_t beams[] = {9, 10, 11, 12, 13};
  ASSERT_FALSE(rig.device().set_interrupted(beams));
  EXPECT_TRUE(rig.silent({'?'}));  // the default request character: not a request
  EXPECT_EQ(only_reply(rig, {'!'}),
            (Bytes{'[',        // start
                   0xBD,       // ~('0'+'9'+'0'+'D'+'0'+'5'): over the characters
                   '0', '9',   // first = 9
                   '0', 'D',   // last = 13
                   '0', '5',   // count = 5
                   ']'}));     // end
}

}  // namespace
}  // namespace rs4sim::metron
