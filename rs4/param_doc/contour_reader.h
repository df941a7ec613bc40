#pragma once
// Internal to rs4/param_doc: one contour of a parameter document — {"runs": [...]},
// {"segments": [529 values]}, {"rectangle": {...}}, {"sector": {...}} or
// {"polygon": [[x, y], ...]} (docs/param.md "Contours") — as the scanner's 529 distances,
// each within `limit_mm`. Refuses (json::Refusal) with the JSON path and the reason.

#include "rs4/param_doc/json_tree.h"
#include "rs4/scanner/geometry.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace rs4sim::rs4::param_doc {

struct ContourLimit {
  std::uint16_t max_mm = 0;
  std::string_view what;  // "protective field limit ([RS4 manual §2.3])"
};

// `unset`: the segments no run covers (0 mm); 0 for the other forms, which set every segment
// (a shape's 0 mm outside it is its documented meaning, docs/param.md "Contours").
scanner::Contour read_contour(const json::Value& v, const std::string& path,
                              const ContourLimit& limit, std::size_t& unset);

}  // namespace rs4sim::rs4::param_doc
