#include "rs4/param_doc/contour_reader.h"

#include <algorithm>

#include "rs4/param_doc/contour_shapes.h"

#include <cmath>
#include <cstdio>
#include <vector>

namespace rs4sim::rs4::param_doc {
namespace {

using json::Value;
using scanner::Contour;
using scanner::kSegmentCount;

constexpr std::int64_t kLastSegment = kSegmentCount - 1;
constexpr double kShapeLimitMm = 1e6;  // coordinates beyond 1 km are typing errors

std::string limit_text(const ContourLimit& limit) { return "mm " + std::string(limit.what); }

std::uint16_t read_mm(const Value& v, const std::string& path, const ContourLimit& limit) {
  return static_cast<std::uint16_t>(json::integer(v, path, 0, limit.max_mm, limit_text(limit)));
}

Contour read_runs(const json::List& runs, const std::string& path, const ContourLimit& limit,
                  std::size_t& unset) {
  Contour c{};
  std::vector<int> owner(kSegmentCount, -1);
  for (int i = 0; i < runs.values_size(); ++i) {
    const std::string at = json::index_path(path, static_cast<std::size_t>(i));
    const auto& run = json::object(runs.values(i), at);
    json::check_keys(run, at, {"from", "to", "mm"});
    for (const auto key : {"from", "to", "mm"}) {
      if (json::find(run, key) == nullptr) {
        json::refuse(DocumentError::kMissingKey, json::key_path(at, key), "required in a run");
      }
    }
    const auto first = json::integer(*json::find(run, "from"), json::key_path(at, "from"), 0,
                                     kLastSegment, "(segment)");
    const auto last = json::integer(*json::find(run, "to"), json::key_path(at, "to"), first,
                                    kLastSegment, "(segment, from..528)");
    const auto mm = read_mm(*json::find(run, "mm"), json::key_path(at, "mm"), limit);
    for (auto n = static_cast<std::size_t>(first); n <= static_cast<std::size_t>(last); ++n) {
      if (owner[n] >= 0) {
        json::refuse(DocumentError::kOutOfRange, at,
                     "segment " + std::to_string(n) + " is also in run " +
                         std::to_string(owner[n]) + " (runs must not overlap)");
      }
      owner[n] = i;
      c[n] = mm;
    }
  }
  unset = static_cast<std::size_t>(std::count(owner.begin(), owner.end(), -1));
  return c;
}

Contour read_segments(const json::List& values, const std::string& path,
                      const ContourLimit& limit) {
  if (static_cast<std::size_t>(values.values_size()) != kSegmentCount) {
    json::refuse(DocumentError::kOutOfRange, path,
                 std::to_string(values.values_size()) + " values, the RS4 has 529 segments");
  }
  Contour c{};
  for (std::size_t n = 0; n < kSegmentCount; ++n) {
    c[n] = read_mm(values.values(static_cast<int>(n)), json::index_path(path, n), limit);
  }
  return c;
}

double read_coordinate(const json::Object& o, const std::string& path, std::string_view key) {
  const Value* v = json::find(o, key);
  const std::string at = json::key_path(path, key);
  if (v == nullptr) json::refuse(DocumentError::kMissingKey, at, "required for this shape");
  const double d = json::number(*v, at);
  if (std::abs(d) > kShapeLimitMm) {
    json::refuse(DocumentError::kOutOfRange, at, "beyond ±1000000 (mm or degrees)");
  }
  return d;
}

std::vector<Point> read_rectangle(const Value& v, const std::string& path) {
  const auto& o = json::object(v, path);
  json::check_keys(o, path, {"x_min_mm", "x_max_mm", "y_min_mm", "y_max_mm"});
  Rectangle r;
  r.x_min_mm = read_coordinate(o, path, "x_min_mm");
  r.x_max_mm = read_coordinate(o, path, "x_max_mm");
  r.y_min_mm = read_coordinate(o, path, "y_min_mm");
  r.y_max_mm = read_coordinate(o, path, "y_max_mm");
  if (!(r.x_min_mm < r.x_max_mm && r.y_min_mm < r.y_max_mm)) {
    json::refuse(DocumentError::kBadShape, path,
                 "needs x_min_mm < x_max_mm and y_min_mm < y_max_mm");
  }
  return rectangle_polygon(r);
}

std::vector<Point> read_polygon(const Value& v, const std::string& path) {
  const auto& points = json::list(v, path);
  std::vector<Point> polygon;
  for (int i = 0; i < points.values_size(); ++i) {
    const std::string at = json::index_path(path, static_cast<std::size_t>(i));
    const auto& xy = json::list(points.values(i), at);
    if (xy.values_size() != 2) {
      json::refuse(DocumentError::kBadShape, at, "a point is [x_mm, y_mm]");
    }
    polygon.push_back({json::number(xy.values(0), json::index_path(at, 0)),
                       json::number(xy.values(1), json::index_path(at, 1))});
    if (std::abs(polygon.back().x_mm) > kShapeLimitMm ||
        std::abs(polygon.back().y_mm) > kShapeLimitMm) {
      json::refuse(DocumentError::kOutOfRange, at, "beyond ±1000000 mm");
    }
  }
  if (polygon.size() < 3) json::refuse(DocumentError::kBadShape, path, "needs at least 3 points");
  if (twice_area(polygon) == 0) json::refuse(DocumentError::kBadShape, path, "has no area");
  return polygon;
}

Distances read_sector(const Value& v, const std::string& path) {
  const auto& o = json::object(v, path);
  json::check_keys(o, path, {"radius_mm", "from_deg", "to_deg"});
  Sector s;
  s.radius_mm = read_coordinate(o, path, "radius_mm");
  s.from_deg = read_coordinate(o, path, "from_deg");
  s.to_deg = read_coordinate(o, path, "to_deg");
  if (!(s.radius_mm > 0)) json::refuse(DocumentError::kBadShape, path, "radius_mm must be > 0");
  if (!(s.from_deg <= s.to_deg)) {
    json::refuse(DocumentError::kBadShape, path, "needs from_deg <= to_deg");
  }
  return sector_distances(s);
}

// Rounded to the nearest mm; a segment beyond the limit refuses the shape.
Contour to_contour(const Distances& d, const std::string& path, const ContourLimit& limit) {
  Contour c{};
  for (std::size_t n = 0; n < kSegmentCount; ++n) {
    const double mm = std::round(d[n]);
    if (mm > limit.max_mm) {
      char b[160];
      std::snprintf(b, sizeof b, "segment %zu (%.2f deg) reaches %.0f mm, beyond 0..%u ", n,
                    scanner::segment_angle_deg(n), mm, static_cast<unsigned>(limit.max_mm));
      json::refuse(DocumentError::kContourOutOfRange, path, b + limit_text(limit));
    }
    c[n] = static_cast<std::uint16_t>(mm);
  }
  return c;
}

}  // namespace

Contour read_contour(const Value& v, const std::string& path, const ContourLimit& limit,
                     std::size_t& unset) {
  unset = 0;
  const auto& o = json::object(v, path);
  json::check_keys(o, path, {"runs", "segments", "rectangle", "sector", "polygon"});
  if (o.fields_size() != 1) {
    json::refuse(DocumentError::kBadShape, path,
                 "exactly one of runs, segments, rectangle, sector, polygon");
  }
  const auto& [key, value] = *o.fields().begin();
  const std::string at = json::key_path(path, key);
  if (key == "runs") return read_runs(json::list(value, at), at, limit, unset);
  if (key == "segments") return read_segments(json::list(value, at), at, limit);
  if (key == "sector") return to_contour(read_sector(value, at), at, limit);
  const auto polygon = key == "rectangle" ? read_rectangle(value, at) : read_polygon(value, at);
  return to_contour(polygon_distances(polygon), at, limit);
}

}  // namespace rs4sim::rs4::param_doc
