#include "rs4/scanner/scene.h"

#include "rs4/scanner/errors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace rs4sim::rs4::scanner {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;
using Work = std::array<double, kSegmentCount>;

bool finite(Point p) { return std::isfinite(p.x) && std::isfinite(p.y); }
double cross(Point a, Point b) { return a.x * b.y - a.y * b.x; }
double angle_deg(Point p) { return std::atan2(p.y, p.x) * kDegPerRad; }

// Calls fn(n) for every segment whose angle lies in [lo, hi] degrees, also for the
// copies of the interval shifted by ±360° (so arcs behind the scanner wrap correctly).
// One index of margin on each side: the exact hit test decides.
template <typename Fn>
void for_each_beam_in(double lo, double hi, Fn&& fn) {
  for (const double shift : {0.0, 360.0, -360.0}) {
    const double first = (lo + shift - kFirstSegmentDeg) / kSegmentStepDeg;
    const double last = (hi + shift - kFirstSegmentDeg) / kSegmentStepDeg;
    if (last < -1.0 || first > static_cast<double>(kSegmentCount)) continue;
    const auto from = static_cast<std::size_t>(std::max(0.0, std::floor(first) - 1.0));
    const auto to = static_cast<std::size_t>(
        std::min(static_cast<double>(kSegmentCount - 1), std::ceil(last) + 1.0));
    for (std::size_t n = from; n <= to; ++n) fn(n);
  }
}

// Ray from the origin along beam n against segment p→q; updates best[n].
void hit_segment(const BeamTable& beams, std::size_t n, Point p, Point q, Work& best) {
  const Point d{beams.cos[n], beams.sin[n]};
  const Point e{q.x - p.x, q.y - p.y};
  const double denom = cross(d, e);
  if (std::abs(denom) < 1e-12) return;  // parallel to the beam
  const double t = cross(p, e) / denom;
  const double u = cross(p, d) / denom;
  if (t < 0.0 || u < 0.0 || u > 1.0) return;
  best[n] = std::min(best[n], t);
}

void render_edge(const BeamTable& beams, Point p, Point q, Work& best) {
  const auto each = [&](std::size_t n) { hit_segment(beams, n, p, q, best); };
  if (std::abs(cross(p, q)) < 1e-9) {  // on a line through the scanner
    for (std::size_t n = 0; n < kSegmentCount; ++n) each(n);
    return;
  }
  double a1 = angle_deg(p);
  double a2 = angle_deg(q);
  if (a1 > a2) std::swap(a1, a2);
  if (a2 - a1 > 180.0) {  // the arc passes ±180°
    std::swap(a1, a2);
    a2 += 360.0;
  }
  for_each_beam_in(a1, a2, each);
}

void render_circle(const BeamTable& beams, const Circle& c, Work& best) {
  const double cc = c.centre.x * c.centre.x + c.centre.y * c.centre.y;
  const double rr = c.radius * c.radius;
  const bool inside = cc <= rr;  // scanner within the outline
  const auto each = [&](std::size_t n) {
    const double b = beams.cos[n] * c.centre.x + beams.sin[n] * c.centre.y;
    const double disc = b * b - (cc - rr);
    if (disc < 0.0) return;
    const double root = std::sqrt(disc);
    const double t = inside ? b + root : b - root;
    if (t >= 0.0) best[n] = std::min(best[n], t);
  };
  if (inside) {
    for (std::size_t n = 0; n < kSegmentCount; ++n) each(n);
    return;
  }
  const double centre = angle_deg(c.centre);
  const double half = std::asin(c.radius / std::sqrt(cc)) * kDegPerRad;
  for_each_beam_in(centre - half, centre + half, each);
}

void render_point(const PointObstacle& p, Work& best) {
  const double a = angle_deg(p.at);
  const double d = std::hypot(p.at.x, p.at.y);
  for (const double shift : {0.0, 360.0}) {
    const double idx = std::round((a + shift - kFirstSegmentDeg) / kSegmentStepDeg);
    if (idx < 0.0 || idx > static_cast<double>(kSegmentCount - 1)) continue;
    auto& slot = best[static_cast<std::size_t>(idx)];
    slot = std::min(slot, d);
  }
}

void render_shape(const BeamTable& beams, const Shape& shape, Work& best) {
  if (const auto* c = std::get_if<Circle>(&shape)) {
    render_circle(beams, *c, best);
  } else if (const auto* poly = std::get_if<Polygon>(&shape)) {
    const auto& v = poly->vertices;
    for (std::size_t i = 0; i < v.size(); ++i)
      render_edge(beams, v[i], v[(i + 1) % v.size()], best);
  } else if (const auto* w = std::get_if<Wall>(&shape)) {
    render_edge(beams, w->a, w->b, best);
  } else if (const auto* p = std::get_if<PointObstacle>(&shape)) {
    render_point(*p, best);
  } else if (const auto* raw = std::get_if<RawContour>(&shape)) {
    for (std::size_t n = 0; n < kSegmentCount; ++n) {
      if (raw->mm[n] != kNoEchoMm) best[n] = std::min(best[n], static_cast<double>(raw->mm[n]));
    }
  }
}

void translate(Point& p, double dx, double dy) {
  p.x += dx;
  p.y += dy;
}

}  // namespace

const BeamTable& beam_table() noexcept {
  static const BeamTable table = [] {
    BeamTable t;
    for (std::size_t n = 0; n < kSegmentCount; ++n) {
      const double rad = segment_angle_deg(n) / kDegPerRad;
      t.cos[n] = std::cos(rad);
      t.sin[n] = std::sin(rad);
    }
    return t;
  }();
  return table;
}

std::string_view to_token(const Shape& shape) {
  struct Token {
    std::string_view operator()(const Circle&) const noexcept { return "circle"; }
    std::string_view operator()(const Polygon&) const noexcept { return "polygon"; }
    std::string_view operator()(const Wall&) const noexcept { return "wall"; }
    std::string_view operator()(const PointObstacle&) const noexcept { return "point"; }
    std::string_view operator()(const RawContour&) const noexcept { return "contour"; }
  };
  return std::visit(Token{}, shape);
}

outcome::std_result<void> check_shape(const Shape& shape) {
  if (const auto* c = std::get_if<Circle>(&shape)) {
    if (!finite(c->centre) || !std::isfinite(c->radius)) return SceneError::kNotFinite;
    if (c->radius <= 0.0) return SceneError::kBadRadius;
  } else if (const auto* poly = std::get_if<Polygon>(&shape)) {
    if (poly->vertices.size() < 3) return SceneError::kTooFewVertices;
    if (!std::all_of(poly->vertices.begin(), poly->vertices.end(), finite))
      return SceneError::kNotFinite;
  } else if (const auto* w = std::get_if<Wall>(&shape)) {
    if (!finite(w->a) || !finite(w->b)) return SceneError::kNotFinite;
    if (w->a.x == w->b.x && w->a.y == w->b.y) return SceneError::kDegenerateWall;
  } else if (const auto* p = std::get_if<PointObstacle>(&shape)) {
    if (!finite(p->at)) return SceneError::kNotFinite;
  } else if (const auto* raw = std::get_if<RawContour>(&shape)) {
    if (raw->mm.size() != kSegmentCount) return SceneError::kRawContourSize;
  }
  return outcome::success();
}

outcome::std_result<ObstacleId> Scene::add(Shape shape) {
  if (obstacles_.size() >= kMaxObstacles) return SceneError::kTooManyObstacles;
  if (auto ok = check_shape(shape); !ok) return ok.error();
  const ObstacleId id = next_id_++;
  obstacles_.push_back(Obstacle{id, std::move(shape)});
  ++revision_;
  return id;
}

outcome::std_result<void> Scene::remove(ObstacleId id) {
  const auto it = std::find_if(obstacles_.begin(), obstacles_.end(),
                               [id](const Obstacle& o) { return o.id == id; });
  if (it == obstacles_.end()) return SceneError::kUnknownObstacle;
  obstacles_.erase(it);
  ++revision_;
  return outcome::success();
}

outcome::std_result<void> Scene::replace(ObstacleId id, Shape shape) {
  const auto it = std::find_if(obstacles_.begin(), obstacles_.end(),
                               [id](const Obstacle& o) { return o.id == id; });
  if (it == obstacles_.end()) return SceneError::kUnknownObstacle;
  if (auto ok = check_shape(shape); !ok) return ok.error();
  it->shape = std::move(shape);
  ++revision_;
  return outcome::success();
}

outcome::std_result<void> Scene::move(ObstacleId id, double dx_mm, double dy_mm) {
  const auto it = std::find_if(obstacles_.begin(), obstacles_.end(),
                               [id](const Obstacle& o) { return o.id == id; });
  if (it == obstacles_.end()) return SceneError::kUnknownObstacle;
  if (!std::isfinite(dx_mm) || !std::isfinite(dy_mm)) return SceneError::kNotFinite;
  Shape moved = it->shape;
  if (auto* c = std::get_if<Circle>(&moved)) {
    translate(c->centre, dx_mm, dy_mm);
  } else if (auto* poly = std::get_if<Polygon>(&moved)) {
    for (auto& v : poly->vertices) translate(v, dx_mm, dy_mm);
  } else if (auto* w = std::get_if<Wall>(&moved)) {
    translate(w->a, dx_mm, dy_mm);
    translate(w->b, dx_mm, dy_mm);
  } else if (auto* p = std::get_if<PointObstacle>(&moved)) {
    translate(p->at, dx_mm, dy_mm);
  } else {
    return SceneError::kNotMovable;
  }
  if (auto ok = check_shape(moved); !ok) return ok.error();
  it->shape = std::move(moved);
  ++revision_;
  return outcome::success();
}

void Scene::clear() {
  obstacles_.clear();
  ++revision_;
}

void Scene::set_max_range_mm(std::uint16_t mm) noexcept {
  max_range_mm_ = std::min<std::uint16_t>(mm, kNoEchoMm - 1);
  ++revision_;
}

void Scene::render(Contour& out) const noexcept {
  Work best;
  best.fill(std::numeric_limits<double>::infinity());
  const BeamTable& beams = beam_table();
  for (const Obstacle& o : obstacles_) render_shape(beams, o.shape, best);
  for (std::size_t n = 0; n < kSegmentCount; ++n) {
    const double mm = std::round(best[n]);
    out[n] = mm <= static_cast<double>(max_range_mm_) ? static_cast<std::uint16_t>(mm) : kNoEchoMm;
  }
}

std::size_t Scene::heap_bytes() const noexcept {
  std::size_t bytes = obstacles_.capacity() * sizeof(Obstacle);
  for (const Obstacle& o : obstacles_) {
    if (const auto* poly = std::get_if<Polygon>(&o.shape))
      bytes += poly->vertices.capacity() * sizeof(Point);
    if (const auto* raw = std::get_if<RawContour>(&o.shape))
      bytes += raw->mm.capacity() * sizeof(std::uint16_t);
  }
  return bytes;
}

}  // namespace rs4sim::rs4::scanner
