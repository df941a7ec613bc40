// Device.ViolateField's obstacle (rs4/scanner/field_evaluation.h), on field pairs written here
// segment by segment, with the distances worked out by hand; then the scanner's own field
// evaluation [RS4 manual §2.3, §2.4] must see exactly the field asked for violated.
#include "rs4/scanner/field_evaluation.h"

#include <gtest/gtest.h>

namespace rs4sim::rs4::scanner {
namespace {

Contour as_contour(const RawContour& raw) {
  Contour c{};
  for (std::size_t n = 0; n < kSegmentCount; ++n) c[n] = raw.mm[n];
  return c;
}

TEST(FieldViolation, ProtectiveObstacleSitsAtHalfTheDistanceOfTheDeepestSegment) {
  FieldPair pair;
  pair.protective_mm[100] = 2000;  // the deepest protective segment
  pair.protective_mm[101] = 1800;
  pair.protective_mm[300] = 1500;
  const auto raw = field_violation(pair, false);
  ASSERT_TRUE(raw);
  ASSERT_EQ(raw->mm.size(), kSegmentCount);
  EXPECT_EQ(raw->mm[99], kNoEchoMm);  // no protective field there: no echo placed
  EXPECT_EQ(raw->mm[100], 1000);      // 2000 / 2
  EXPECT_EQ(raw->mm[101], 900);       // 1800 / 2
  EXPECT_EQ(raw->mm[102], kNoEchoMm);
  EXPECT_EQ(raw->mm[300], kNoEchoMm);  // only the three beams around segment 100
  const auto flags = evaluate(as_contour(*raw), pair);
  EXPECT_TRUE(flags.protective_violated());
  EXPECT_EQ(flags.protective.count(), 2U);
}

TEST(FieldViolation, WarningObstacleLiesBetweenTheTwoBoundariesOnly) {
  FieldPair pair;
  for (std::size_t n = 0; n < kSegmentCount; ++n) {
    pair.protective_mm[n] = 1000;
    pair.warning_mm[n] = 1200;
  }
  pair.warning_mm[0] = 3000;  // the most room beyond the protective field: segment 0
  const auto raw = field_violation(pair, true);
  ASSERT_TRUE(raw);
  EXPECT_EQ(raw->mm[0], 2000);  // 1000 + (3000 - 1000) / 2
  EXPECT_EQ(raw->mm[1], 1100);  // 1000 + (1200 - 1000) / 2
  EXPECT_EQ(raw->mm[2], kNoEchoMm);
  const auto flags = evaluate(as_contour(*raw), pair);
  EXPECT_TRUE(flags.warning_violated());
  EXPECT_FALSE(flags.protective_violated());
}

TEST(FieldViolation, LastSegmentKeepsItsNeighbourInside) {
  FieldPair pair;
  pair.protective_mm[kSegmentCount - 1] = 500;
  pair.protective_mm[kSegmentCount - 2] = 400;
  const auto raw = field_violation(pair, false);
  ASSERT_TRUE(raw);
  EXPECT_EQ(raw->mm[kSegmentCount - 1], 250);
  EXPECT_EQ(raw->mm[kSegmentCount - 2], 200);
  EXPECT_EQ(raw->mm[kSegmentCount - 3], kNoEchoMm);
}

TEST(FieldViolation, NoFieldOrTooLittleOfItGivesNone) {
  EXPECT_FALSE(field_violation(FieldPair{}, false));
  EXPECT_FALSE(field_violation(FieldPair{}, true));
  FieldPair shallow;
  shallow.protective_mm[10] = 19;  // under 20 mm of field
  EXPECT_FALSE(field_violation(shallow, false));
  shallow.protective_mm[10] = 20;
  EXPECT_TRUE(field_violation(shallow, false));
  FieldPair no_warning_room;  // warning not beyond protective anywhere
  no_warning_room.protective_mm[10] = 1000;
  no_warning_room.warning_mm[10] = 1000;
  EXPECT_FALSE(field_violation(no_warning_room, true));
}

}  // namespace
}  // namespace rs4sim::rs4::scanner
