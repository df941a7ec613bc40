#include "rs4/param_doc/contour_shapes.h"

#include <algorithm>
#include <cmath>

namespace rs4sim::rs4::param_doc {
namespace {

constexpr double kEpsilon = 1e-9;

double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// Largest t ≥ 0 with t·(c, s) on the edge a→b; -1 when the beam misses it.
double crossing(double c, double s, const Point& a, const Point& b) {
  const double ex = b.x_mm - a.x_mm;
  const double ey = b.y_mm - a.y_mm;
  const double denom = cross(c, s, ex, ey);
  if (std::abs(denom) < kEpsilon) {  // parallel: on the beam only when collinear
    if (std::abs(cross(c, s, a.x_mm, a.y_mm)) > kEpsilon * std::max(1.0, std::abs(a.x_mm))) {
      return -1;
    }
    const double t = std::max(c * a.x_mm + s * a.y_mm, c * b.x_mm + s * b.y_mm);
    return t >= 0 ? t : -1;
  }
  const double t = cross(a.x_mm, a.y_mm, ex, ey) / denom;
  const double lambda = cross(a.x_mm, a.y_mm, c, s) / denom;
  if (t < 0 || lambda < -kEpsilon || lambda > 1 + kEpsilon) return -1;
  return t;
}

}  // namespace

Distances polygon_distances(std::span<const Point> polygon) {
  Distances d{};
  const auto& beams = scanner::beam_table();
  for (std::size_t n = 0; n < scanner::kSegmentCount; ++n) {
    double farthest = 0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const Point& a = polygon[i];
      const Point& b = polygon[(i + 1) % polygon.size()];
      farthest = std::max(farthest, crossing(beams.cos[n], beams.sin[n], a, b));
    }
    d[n] = farthest;
  }
  return d;
}

std::vector<Point> rectangle_polygon(const Rectangle& r) {
  return {{r.x_min_mm, r.y_min_mm},
          {r.x_max_mm, r.y_min_mm},
          {r.x_max_mm, r.y_max_mm},
          {r.x_min_mm, r.y_max_mm}};
}

Distances sector_distances(const Sector& s) {
  Distances d{};
  for (std::size_t n = 0; n < scanner::kSegmentCount; ++n) {
    const double angle = scanner::segment_angle_deg(n);
    const bool inside = angle >= s.from_deg - kEpsilon && angle <= s.to_deg + kEpsilon;
    d[n] = inside ? s.radius_mm : 0;
  }
  return d;
}

double twice_area(std::span<const Point> polygon) {
  double sum = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point& a = polygon[i];
    const Point& b = polygon[(i + 1) % polygon.size()];
    sum += cross(a.x_mm, a.y_mm, b.x_mm, b.y_mm);
  }
  return sum;
}

std::vector<Run> runs_of(const scanner::Contour& contour) {
  std::vector<Run> runs;
  for (std::size_t n = 0; n < contour.size(); ++n) {
    if (!runs.empty() && runs.back().mm == contour[n]) {
      runs.back().last = n;
    } else {
      runs.push_back(Run{n, n, contour[n]});
    }
  }
  return runs;
}

}  // namespace rs4sim::rs4::param_doc
