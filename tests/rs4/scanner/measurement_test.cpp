// Flagged measurement values ([RS4 manual §5.2.3.4]: bit 0 = a protective field was violated
// between this value and the previous one; stop is always output).
#include "rs4/scanner/measurement.h"

#include <gtest/gtest.h>

namespace rs4sim::rs4::scanner {
namespace {

Contour constant(std::uint16_t mm) {
  Contour c{};
  c.fill(mm);
  return c;
}

// [RS4 manual §5.2.3.4] example window: start 0, stop 528, resolution 4 → segments 0, 4, …, 528.
TEST(ScannerMeasurement, FlagCoversTheSegmentsSinceThePreviousValue) {
  SegmentFlags prot;
  prot.set(5);
  prot.set(6);
  const Contour out = measurement_contour(constant(1001), prot, MeasurementOutput{4, 0, 528});
  EXPECT_EQ(out[0], 1000);   // 1001 with bit 0 cleared, no violation at 0
  EXPECT_EQ(out[4], 1000);   // covers 1..4
  EXPECT_EQ(out[8], 1001);   // covers 5..8: violated
  EXPECT_EQ(out[12], 1000);  // covers 9..12
  EXPECT_EQ(out[528], 1000);
  EXPECT_EQ(out[5], 1001);  // not an output segment: its own flag
}

TEST(ScannerMeasurement, StopIsAlwaysOutputAndFlagged) {
  SegmentFlags prot;
  prot.set(9);
  const Contour out = measurement_contour(constant(2000), prot, MeasurementOutput{4, 0, 10});
  EXPECT_EQ(out[8], 2000);   // covers 5..8
  EXPECT_EQ(out[10], 2001);  // stop (10 − 0 not a multiple of 4) covers 9..10
}

TEST(ScannerMeasurement, FirstValueCarriesOnlyItsOwnSegment) {
  SegmentFlags prot;
  prot.set(99);
  const Contour out = measurement_contour(constant(500), prot, MeasurementOutput{2, 100, 104});
  EXPECT_EQ(out[100], 500);
  prot.set(100);
  EXPECT_EQ(measurement_contour(constant(500), prot, MeasurementOutput{2, 100, 104})[100], 501);
}

TEST(ScannerMeasurement, InvalidWindowKeepsPerSegmentFlags) {
  SegmentFlags prot;
  prot.set(3);
  const Contour out = measurement_contour(constant(700), prot, MeasurementOutput{0, 0, 528});
  EXPECT_EQ(out[3], 701);
  EXPECT_EQ(out[4], 700);
  EXPECT_EQ(measurement_contour(constant(700), prot, MeasurementOutput{1, 10, 529})[3], 701);
}

TEST(ScannerMeasurement, NoEchoStaysEven) {
  const Contour out =
      measurement_contour(constant(kNoEchoMm), SegmentFlags{}, MeasurementOutput{1, 0, 528});
  EXPECT_EQ(out[0], 0xFFFE);
}

}  // namespace
}  // namespace rs4sim::rs4::scanner
