#pragma once
// The world around the simulated scanner (docs/rs4-scanner.md "Scene"). Obstacles are
// given in scanner coordinates (geometry.h: mm, +x along 0°, +y along 90°). Circles and
// polygons are outlines: a beam stops at the first edge it meets, so a polygon drawn
// around the scanner models the walls of a room. Every scan renders the scene into a
// 529-segment contour: the nearest hit along each beam, kNoEchoMm beyond the range.

#include "rs4/scanner/geometry.h"

#include <boost/outcome/std_result.hpp>

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <variant>
#include <vector>

namespace rs4sim::rs4::scanner {

namespace outcome = boost::outcome_v2;

struct Point {
  double x = 0;
  double y = 0;
};
struct Circle {
  Point centre;
  double radius = 0;
};
struct Polygon {  // closed outline, convex or concave
  std::vector<Point> vertices;
};
struct Wall {  // a line segment
  Point a;
  Point b;
};
struct PointObstacle {  // a thin object: hits only the beam nearest to its angle
  Point at;
};
struct RawContour {  // 529 distances in mm (kNoEchoMm = nothing), merged by min
  std::vector<std::uint16_t> mm;
};
using Shape = std::variant<Circle, Polygon, Wall, PointObstacle, RawContour>;
// "circle", "polygon", "wall", "point", "contour" (the API's word: the request field that
// carries the shape).
[[nodiscard]] std::string_view to_token(const Shape& shape);

using ObstacleId = std::uint32_t;
struct Obstacle {
  ObstacleId id = 0;
  Shape shape;
};

class Scene {
 public:
  static constexpr std::size_t kMaxObstacles = 256;
  // Beams longer than this see no echo (project assumption: 50 m, docs/rs4-scanner.md).
  static constexpr std::uint16_t kDefaultMaxRangeMm = 50000;

  outcome::std_result<ObstacleId> add(Shape shape);
  outcome::std_result<void> remove(ObstacleId id);
  outcome::std_result<void> replace(ObstacleId id, Shape shape);
  outcome::std_result<void> move(ObstacleId id, double dx_mm, double dy_mm);
  void clear();

  [[nodiscard]] const std::vector<Obstacle>& obstacles() const noexcept { return obstacles_; }
  // Changes on every successful edit; the scanner re-renders only when it changed.
  [[nodiscard]] std::uint64_t revision() const noexcept { return revision_; }

  void set_max_range_mm(std::uint16_t mm) noexcept;
  [[nodiscard]] std::uint16_t max_range_mm() const noexcept { return max_range_mm_; }

  // Nearest hit per beam, rounded to whole mm; kNoEchoMm where nothing is within range.
  void render(Contour& out) const noexcept;

  [[nodiscard]] std::size_t heap_bytes() const noexcept;

 private:
  std::vector<Obstacle> obstacles_;
  ObstacleId next_id_ = 1;
  std::uint64_t revision_ = 0;
  std::uint16_t max_range_mm_ = kDefaultMaxRangeMm;
};

// Checks one shape (finite coordinates, radius, vertex count, contour size).
outcome::std_result<void> check_shape(const Shape& shape);

}  // namespace rs4sim::rs4::scanner
