// Scene → contour, checked against geometry computed here from plain trigonometry
// (segment n at −5.04° + n·0.36°, [RS4 manual §2.3]; +x = 0°, +y = 90°).
#include "rs4/scanner/scene.h"

#include "rs4/scanner/errors.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rs4sim::rs4::scanner {
namespace {

double rad(double deg) { return deg * std::numbers::pi / 180.0; }
double theta(std::size_t n) { return rad(-5.04 + 0.36 * static_cast<double>(n)); }

Contour render(const Scene& s) {
  Contour c{};
  s.render(c);
  return c;
}

TEST(ScannerScene, EmptySceneHasNoEcho) {
  const Contour c = render(Scene{});
  for (const auto v : c) EXPECT_EQ(v, kNoEchoMm);
}

TEST(ScannerScene, SegmentAngles) {
  EXPECT_DOUBLE_EQ(segment_angle_deg(0), -5.04);
  EXPECT_NEAR(segment_angle_deg(14), 0.0, 1e-9);
  EXPECT_NEAR(segment_angle_deg(264), 90.0, 1e-9);
  EXPECT_NEAR(segment_angle_deg(528), 185.04, 1e-9);
}

// Circle r = 100 mm, centre 2000 mm straight ahead (90°). A beam at angle φ off the
// centre line passes the centre at 2000·sin φ; it hits while that is ≤ 100, i.e.
// |φ| ≤ asin(0.05) = 2.866°, so segments 264 ± 7 (0.36° steps), at
// 2000·cos φ − sqrt(100² − (2000·sin φ)²).
TEST(ScannerScene, CircleStraightAhead) {
  Scene s;
  ASSERT_TRUE(s.add(Circle{{0, 2000}, 100}));
  const Contour c = render(s);
  EXPECT_EQ(c[264], 1900);
  EXPECT_EQ(c[256], kNoEchoMm);
  EXPECT_EQ(c[272], kNoEchoMm);
  for (std::size_t n = 257; n <= 271; ++n) {
    const double phi = rad(0.36 * (static_cast<double>(n) - 264.0));
    const double off = 2000.0 * std::sin(phi);
    const double expected = 2000.0 * std::cos(phi) - std::sqrt(100.0 * 100.0 - off * off);
    EXPECT_NEAR(c[n], expected, 0.5) << "segment " << n;
  }
  std::size_t hits = 0;
  for (const auto v : c) hits += v != kNoEchoMm ? 1U : 0U;
  EXPECT_EQ(hits, 15U);
}

// A wall y = 1000 from x = −5000 to 5000: beam θ hits at 1000 / sin θ where
// |1000·cot θ| ≤ 5000, i.e. 11.31° ≤ θ ≤ 168.69°.
TEST(ScannerScene, WallAcrossTheFront) {
  Scene s;
  ASSERT_TRUE(s.add(Wall{{-5000, 1000}, {5000, 1000}}));
  const Contour c = render(s);
  const double lo = std::atan2(1000.0, 5000.0);
  for (std::size_t n = 0; n < kSegmentCount; ++n) {
    const double t = theta(n);
    if (t < lo - 1e-9 || t > std::numbers::pi - lo + 1e-9) {
      EXPECT_EQ(c[n], kNoEchoMm) << "segment " << n;
    } else {
      EXPECT_NEAR(c[n], 1000.0 / std::sin(t), 0.5) << "segment " << n;
    }
  }
  EXPECT_EQ(c[264], 1000);
}

// A point at (1000, 0) lies on the 0° beam = segment 14; no other beam sees it.
TEST(ScannerScene, PointOnTheZeroDegreeBeam) {
  Scene s;
  ASSERT_TRUE(s.add(PointObstacle{{1000, 0}}));
  const Contour c = render(s);
  EXPECT_EQ(c[14], 1000);
  EXPECT_EQ(c[13], kNoEchoMm);
  EXPECT_EQ(c[15], kNoEchoMm);
}

// A room around the scanner: x = ±3000, y from −1000 to 3000. Beam θ meets the
// right wall at 3000/cos θ, the far wall at 3000/sin θ, the left wall at −3000/cos θ.
TEST(ScannerScene, RoomPolygonAroundTheScanner) {
  Scene s;
  ASSERT_TRUE(s.add(Polygon{{{-3000, -1000}, {3000, -1000}, {3000, 3000}, {-3000, 3000}}}));
  const Contour c = render(s);
  for (std::size_t n = 0; n < kSegmentCount; ++n) {
    const double t = theta(n);
    // Leaving a convex room: the nearest of the wall crossings ahead of the scanner.
    double expected = 1e9;
    if (std::cos(t) > 1e-12) expected = std::min(expected, 3000.0 / std::cos(t));
    if (std::cos(t) < -1e-12) expected = std::min(expected, -3000.0 / std::cos(t));
    if (std::sin(t) > 1e-12) expected = std::min(expected, 3000.0 / std::sin(t));
    if (std::sin(t) < -1e-12) expected = std::min(expected, -1000.0 / std::sin(t));
    EXPECT_NEAR(c[n], expected, 0.5) << "segment " << n;
  }
  EXPECT_EQ(c[0], 3012);  // 3000 / cos 5.04° = 3011.6
}

// A concave U opening towards the scanner: the straight-ahead beam passes the gap
// (|x| < 500 at y = 2000) and meets the back at y = 3000; segment 207 (69.48°) meets
// the lower edge y = 2000 at x = 2000/tan 69.48° = 748 mm, i.e. at 2000 / sin 69.48°.
TEST(ScannerScene, ConcavePolygon) {
  Scene s;
  ASSERT_TRUE(s.add(Polygon{{{-1000, 2000},
                             {-500, 2000},
                             {-500, 3000},
                             {500, 3000},
                             {500, 2000},
                             {1000, 2000},
                             {1000, 4000},
                             {-1000, 4000}}}));
  const Contour c = render(s);
  EXPECT_EQ(c[264], 3000);
  EXPECT_NEAR(c[207], 2000.0 / std::sin(theta(207)), 0.5);
  // Segment 255 (86.76°): x at y = 3000 is 170 → the back edge, 3000 / sin θ.
  EXPECT_NEAR(c[255], 3000.0 / std::sin(theta(255)), 0.5);
}

// Circle just behind the 180° side: centre (−3000, −100), r = 500. Its centre lies at
// 181.91°; beams from 180.36° to 185.04° see it at |c|·cos φ − sqrt(r² − (|c|·sin φ)²).
TEST(ScannerScene, CircleAcrossThe180DegreeSide) {
  Scene s;
  ASSERT_TRUE(s.add(Circle{{-3000, -100}, 500}));
  const Contour c = render(s);
  const double dist = std::hypot(3000.0, 100.0);
  const double centre = std::atan2(-100.0, -3000.0) + 2.0 * std::numbers::pi;
  std::size_t hits = 0;
  for (std::size_t n = 0; n < kSegmentCount; ++n) {
    const double phi = theta(n) - centre;
    const double off = dist * std::sin(phi);
    if (std::abs(off) > 500.0 || std::cos(phi) < 0) {
      EXPECT_EQ(c[n], kNoEchoMm) << n;
      continue;
    }
    ++hits;
    EXPECT_NEAR(c[n], dist * std::cos(phi) - std::sqrt(500.0 * 500.0 - off * off), 0.5) << n;
  }
  EXPECT_GT(hits, 20U);
  EXPECT_NE(c[528], kNoEchoMm);
}

TEST(ScannerScene, RawContourMergesByMinimumAndRange) {
  Scene s;
  std::vector<std::uint16_t> raw(kSegmentCount, kNoEchoMm);
  raw[264] = 1500;
  raw[100] = 800;
  ASSERT_TRUE(s.add(RawContour{raw}));
  ASSERT_TRUE(s.add(Circle{{0, 2000}, 100}));
  const Contour c = render(s);
  EXPECT_EQ(c[264], 1500);  // raw is nearer than the circle (1900)
  EXPECT_EQ(c[265], c[263]);
  EXPECT_EQ(c[100], 800);
  s.set_max_range_mm(700);
  EXPECT_EQ(render(s)[100], kNoEchoMm);
}

TEST(ScannerScene, BeyondMaxRangeIsNoEcho) {
  Scene s;
  ASSERT_TRUE(s.add(Circle{{0, 60000}, 100}));
  EXPECT_EQ(render(s)[264], kNoEchoMm);
  s.set_max_range_mm(65000);
  EXPECT_EQ(render(s)[264], 59900);
}

TEST(ScannerScene, EditsAndTheirErrors) {
  Scene s;
  const auto id = s.add(Circle{{0, 2000}, 100});
  ASSERT_TRUE(id);
  const auto rev = s.revision();
  ASSERT_TRUE(s.move(id.value(), 0, 1000));
  EXPECT_GT(s.revision(), rev);
  EXPECT_EQ(render(s)[264], 2900);
  EXPECT_EQ(s.move(999, 1, 1).error(), SceneError::kUnknownObstacle);
  EXPECT_EQ(s.add(Circle{{0, 1}, 0}).error(), SceneError::kBadRadius);
  EXPECT_EQ(s.add(Circle{{NAN, 1}, 5}).error(), SceneError::kNotFinite);
  EXPECT_EQ(s.add(Polygon{{{0, 1}, {1, 1}}}).error(), SceneError::kTooFewVertices);
  EXPECT_EQ(s.add(Wall{{1, 1}, {1, 1}}).error(), SceneError::kDegenerateWall);
  EXPECT_EQ(s.add(RawContour{std::vector<std::uint16_t>(528, 0)}).error(),
            SceneError::kRawContourSize);
  const auto raw = s.add(RawContour{std::vector<std::uint16_t>(kSegmentCount, kNoEchoMm)});
  ASSERT_TRUE(raw);
  EXPECT_EQ(s.move(raw.value(), 1, 1).error(), SceneError::kNotMovable);
  EXPECT_EQ(s.move(id.value(), INFINITY, 0).error(), SceneError::kNotFinite);
  ASSERT_TRUE(s.replace(id.value(), Wall{{-100, 500}, {100, 500}}));
  EXPECT_EQ(render(s)[264], 500);
  ASSERT_TRUE(s.remove(id.value()));
  EXPECT_EQ(s.remove(id.value()).error(), SceneError::kUnknownObstacle);
  EXPECT_EQ(render(s)[264], kNoEchoMm);
}

TEST(ScannerScene, ObstacleLimit) {
  Scene s;
  for (std::size_t i = 0; i < Scene::kMaxObstacles; ++i)
    ASSERT_TRUE(s.add(PointObstacle{{0, 100}}));
  EXPECT_EQ(s.add(PointObstacle{{0, 100}}).error(), SceneError::kTooManyObstacles);
}

// The API names a refused shape by the request field that carried it (AddObstacle's
// circle/polygon/wall/point/contour).
TEST(ScannerScene, EveryShapeHasItsApiWord) {
  EXPECT_EQ(to_token(Shape{Circle{{0, 0}, 10}}), "circle");
  EXPECT_EQ(to_token(Shape{Polygon{}}), "polygon");
  EXPECT_EQ(to_token(Shape{Wall{}}), "wall");
  EXPECT_EQ(to_token(Shape{PointObstacle{}}), "point");
  EXPECT_EQ(to_token(Shape{RawContour{}}), "contour");
}

}  // namespace
}  // namespace rs4sim::rs4::scanner
