// Standard line mode's report message in its six shapes with and without checksum, against
// Table 1's lengths, and Equations 1-3 [METRON manual "Standard line mode", "Slave line
// mode"]. STX/ETX, ',' and the raw checksum byte are the project's EXTENSION.
#include "metron/standard_report.h"

#include <gtest/gtest.h>

#include <vector>

namespace rs4sim::metron {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;

// first = 9, last = 13, count = 5 (beams 9..13 interrupted)
const Bytes kValues{0x09, 0x0D, 0x05};

Bytes report(Format f, bool sep, bool cks) {
  return encode_report(kValues, {f, sep, cks}, WireTable{}, ChecksumReading::kModulo256);
}

TEST(MetronReport, Binary) {
  EXPECT_EQ(report(Format::kBinary, false, false), (Bytes{0x02, 0x09, 0x0D, 0x05, 0x03}));
  EXPECT_EQ(report(Format::kBinary, true, false),
            (Bytes{0x02, 0x09, 0x2C, 0x0D, 0x2C, 0x05, 0x03}));
  EXPECT_EQ(report(Format::kBinary, false, true),
            (Bytes{0x02, 0x09, 0x0D, 0x05, 0xE4 /* ~(9+13+5) */, 0x03}));
  EXPECT_EQ(report(Format::kBinary, true, true),
            (Bytes{0x02, 0x09, 0x2C, 0x0D, 0x2C, 0x05, 0xE4, 0x03}));
}

TEST(MetronReport, Hex) {
  EXPECT_EQ(report(Format::kHex, false, false), (Bytes{0x02, '0', '9', '0', 'D', '0', '5', 0x03}));
  EXPECT_EQ(report(Format::kHex, true, true),
            (Bytes{0x02, '0', '9', ',', '0', 'D', ',', '0', '5', 0xE4, 0x03}));
}

TEST(MetronReport, Decimal) {
  EXPECT_EQ(report(Format::kDecimal, false, false),
            (Bytes{0x02, '0', '0', '9', '0', '1', '3', '0', '0', '5', 0x03}));
  EXPECT_EQ(report(Format::kDecimal, true, false),
            (Bytes{0x02, '0', '0', '9', ',', '0', '1', '3', ',', '0', '0', '5', 0x03}));
  const Bytes big{255};
  EXPECT_EQ(encode_report(big, {Format::kDecimal, false, false}, WireTable{},
                          ChecksumReading::kModulo256),
            (Bytes{0x02, '2', '5', '5', 0x03}));
}

TEST(MetronReport, LengthsAreTable1) {
  for (std::size_t n = 1; n <= 16; ++n) {
    const Bytes values(n, 0x42);
    const std::size_t expected[3][2] = {
        {n + 2, 2 * n + 1}, {2 * n + 2, 3 * n + 1}, {3 * n + 2, 4 * n + 1}};
    for (int f = 0; f < 3; ++f)
      for (int sep = 0; sep < 2; ++sep)
        for (int cks = 0; cks < 2; ++cks) {
          const ReportFormat rf{static_cast<Format>(f), sep == 1, cks == 1};
          const auto want = expected[f][sep] + static_cast<std::size_t>(cks);
          EXPECT_EQ(report_length(n, rf), want);
          EXPECT_EQ(encode_report(values, rf, WireTable{}, ChecksumReading::kModulo256).size(),
                    want);
        }
  }
}

TEST(MetronReport, SendTimeIsEquation1And2) {
  // Equation 1 (parity): 5 * 11 / 19200 s = 2.864583 ms, + 1 ms
  EXPECT_EQ(send_time(5, {19200, 8, stream::Parity::kEven, 1}), 3'864'584ns);
  // Equation 2 (no parity): 5 * 10 / 9600 s = 5.208333 ms, + 1 ms
  EXPECT_EQ(send_time(5, {9600, 8, stream::Parity::kNone, 1}), 6'208'334ns);
}

TEST(MetronReport, ReplyDelayIsEquation3) {
  EXPECT_EQ(reply_delay(4, 20ms), 12'291'667ns);
  EXPECT_EQ(reply_delay(10, 30ms), 15ms + 5'729'167ns);  // 110 bits at 19200
}

}  // namespace
}  // namespace rs4sim::metron
