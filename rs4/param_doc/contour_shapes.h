#pragma once
// Simple shapes as RS4 contours (docs/param.md "Shapes"). A contour holds one distance per
// segment ([RS4 manual §2.3]: 529 segments, segment n at −5.04° + n·0.36°); a field is
// everything between the scanner and the contour along each beam. A shape is converted by
// one rule: segment n gets the largest distance t ≥ 0 at which its beam (from the origin,
// in scanner coordinates, rs4/scanner/geometry.h) still meets the shape, 0 when the beam
// misses it. The field is therefore the shape plus the shadow between the scanner and it.
// Distances stay doubles here; the caller rounds (to nearest mm) and checks the limits.

#include "rs4/scanner/geometry.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rs4sim::rs4::param_doc {

using Distances = std::array<double, scanner::kSegmentCount>;  // mm per segment

struct Point {
  double x_mm = 0;
  double y_mm = 0;
};

// Axis-parallel: x_min < x_max, y_min < y_max (+y = straight ahead, segment 264).
struct Rectangle {
  double x_min_mm = 0;
  double x_max_mm = 0;
  double y_min_mm = 0;
  double y_max_mm = 0;
};

// A circle sector centred on the scanner: radius on every segment whose angle lies in
// [from_deg, to_deg], 0 elsewhere.
struct Sector {
  double radius_mm = 0;
  double from_deg = 0;
  double to_deg = 0;
};

// The farthest crossing of each beam with the polygon's edges (closed: last → first).
Distances polygon_distances(std::span<const Point> polygon);
std::vector<Point> rectangle_polygon(const Rectangle& r);
Distances sector_distances(const Sector& s);
// Twice the signed area (shoelace); 0 for a degenerate polygon.
double twice_area(std::span<const Point> polygon);

// Consecutive segments of equal distance, first..last inclusive: the compact form a
// document shows a contour in.
struct Run {
  std::size_t first = 0;
  std::size_t last = 0;
  std::uint16_t mm = 0;
};
std::vector<Run> runs_of(const scanner::Contour& contour);

}  // namespace rs4sim::rs4::param_doc
