// ParityMarks against the byte sequences termios delivers with INPCK | PARMRK
// [termios(3) PARMRK]: FF 00 X for a character X received with a parity error, FF FF for a
// literal FF. The frames are the METRON's "Request OSSD status" 02 01 0C F3 [METRON manual
// "No node"] with one character damaged, and a Modbus RTU CRC holding FF.
#include "stream/parity_marks.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace rs4sim::stream {
namespace {

using Bytes = std::vector<std::uint8_t>;

// The decoded line as text: good runs as hex, a damaged character as "!XX".
struct Seen {
  std::string text;
  void feed(ParityMarks& m, const Bytes& chunk) {
    m.feed(
        chunk,
        [this](std::span<const std::uint8_t> b) {
          for (const auto c : b) text += hex(c) + " ";
        },
        [this](std::uint8_t c) { text += "!" + hex(c) + " "; });
  }
  // The text of one chunk fed to `m`.
  static std::string of(ParityMarks& m, const Bytes& chunk) {
    Seen s;
    s.feed(m, chunk);
    return s.text;
  }
  static std::string hex(std::uint8_t c) {
    static constexpr char kDigits[] = "0123456789ABCDEF";
    return {kDigits[c >> 4], kDigits[c & 0x0F]};
  }
};

TEST(ParityMarks, PlainBytesPassThrough) {
  ParityMarks m;
  EXPECT_EQ(Seen::of(m, {0x02, 0x01, 0x0C, 0xF3}), "02 01 0C F3 ");
  EXPECT_EQ(m.damaged_count(), 0U);
}

TEST(ParityMarks, DamagedCharacterIsSeparatedInLineOrder) {
  ParityMarks m;
  // 02 01, then 0C with a parity error (FF 00 0C), then F3
  EXPECT_EQ(Seen::of(m, {0x02, 0x01, 0xFF, 0x00, 0x0C, 0xF3}), "02 01 !0C F3 ");
  EXPECT_EQ(m.damaged_count(), 1U);
  EXPECT_EQ(m.pending(), 0U);
}

TEST(ParityMarks, LiteralFfIsOneByte) {
  ParityMarks m;
  // slave 3, FC 3|0x80 ... a CRC byte FF doubled by the port
  EXPECT_EQ(Seen::of(m, {0x03, 0x83, 0x07, 0xFF, 0xFF, 0x32}), "03 83 07 FF 32 ");
  EXPECT_EQ(m.damaged_count(), 0U);
}

TEST(ParityMarks, DamagedFfAndBreak) {
  ParityMarks m;
  // FF damaged; a break (NUL damaged)
  EXPECT_EQ(Seen::of(m, {0xFF, 0x00, 0xFF, 0xFF, 0x00, 0x00}), "!FF !00 ");
  EXPECT_EQ(m.damaged_count(), 2U);
}

TEST(ParityMarks, MarkSplitAcrossReads) {
  for (std::size_t cut = 1; cut < 6; ++cut) {
    const Bytes line{0x02, 0xFF, 0x00, 0x01, 0xFF, 0xFF};
    ParityMarks m;
    Seen s;
    s.feed(m, Bytes(line.begin(), line.begin() + static_cast<std::ptrdiff_t>(cut)));
    s.feed(m, Bytes(line.begin() + static_cast<std::ptrdiff_t>(cut), line.end()));
    EXPECT_EQ(s.text, "02 !01 FF ") << "cut after " << cut;
    EXPECT_EQ(m.pending(), 0U);
  }
  ParityMarks m;
  Seen s;
  s.feed(m, {0x02, 0xFF});
  EXPECT_EQ(s.text, "02 ");
  EXPECT_EQ(m.pending(), 1U);
  s.feed(m, {0x00});
  EXPECT_EQ(m.pending(), 2U);
  s.feed(m, {0x0C});
  EXPECT_EQ(s.text, "02 !0C ");
}

TEST(ParityMarks, StrayMarkDeliveredAsReceived) {
  ParityMarks m;
  EXPECT_EQ(Seen::of(m, {0xFF, 0x41}), "FF 41 ");  // not something termios sends: kept, counted
  EXPECT_EQ(m.stray_marks(), 1U);
  EXPECT_EQ(m.damaged_count(), 0U);
}

}  // namespace
}  // namespace rs4sim::stream
