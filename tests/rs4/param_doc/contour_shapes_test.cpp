// Shape-to-contour conversion (docs/param.md "Shapes"): distances computed by hand.
#include "rs4/param_doc/contour_shapes.h"

#include <gtest/gtest.h>

namespace rs4sim::rs4::param_doc {
namespace {

TEST(ContourShapes, SquareAroundTheScanner) {
  const auto d = polygon_distances(rectangle_polygon({-1000, 1000, -1000, 1000}));
  EXPECT_NEAR(d[14], 1000.0, 1e-6);               // 0°
  EXPECT_NEAR(d[139], 1414.2135623730951, 1e-6);  // 45°: the corner
  EXPECT_NEAR(d[264], 1000.0, 1e-6);              // 90°
  EXPECT_NEAR(d[514], 1000.0, 1e-6);              // 180°
}

TEST(ContourShapes, BeamMissingTheShapeIsZero) {
  // A square straight ahead, 1000..2000 mm: the 0° beam misses it.
  const auto d = polygon_distances(rectangle_polygon({-500, 500, 1000, 2000}));
  EXPECT_EQ(d[14], 0.0);
  EXPECT_NEAR(d[264], 2000.0, 1e-6);  // the far edge, not the near one
}

TEST(ContourShapes, SectorIsInclusiveOfItsEdges) {
  const auto d = sector_distances({1500, -5.04, 0});
  EXPECT_EQ(d[0], 1500);
  EXPECT_EQ(d[14], 1500);
  EXPECT_EQ(d[15], 0);
}

TEST(ContourShapes, RunsOfEqualDistances) {
  scanner::Contour c{};
  c.fill(5);
  c[3] = 7;
  c[4] = 7;
  const auto runs = runs_of(c);
  ASSERT_EQ(runs.size(), 3U);
  EXPECT_EQ(runs[0].last, 2U);
  EXPECT_EQ(runs[1].first, 3U);
  EXPECT_EQ(runs[1].mm, 7);
  EXPECT_EQ(runs[2].last, 528U);
}

TEST(ContourShapes, TwiceAreaOfAUnitSquare) {
  const Point square[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_EQ(twice_area(square), 2.0);
}

}  // namespace
}  // namespace rs4sim::rs4::param_doc
