#pragma once
// The difference of two RS4 parameter sets in terms of their fields: which options
// changed (old → new), which user passwords changed (never their values,
// [RS4 manual §7.2.4]), the device identity apart, and per field pair and contour the
// ranges of consecutive changed segments with the largest change in mm.

#include "rs4/report/parameter_fields.h"
#include "rs4/scanner/parameter_set.h"

#include <cstddef>
#include <string>
#include <vector>

namespace rs4sim::rs4::report {

struct ValueChange {
  std::string field;  // e.g. "response_time_ms", "permitted.from_pair_2", "serial_number"
  std::string old_value;
  std::string new_value;
  bool operator==(const ValueChange&) const = default;
};

// Segments first..last (inclusive, 0..528) all changed; `max_change_mm` is the signed
// change (new − old) of largest magnitude in the range (the first one on a tie).
struct SegmentRange {
  std::size_t first = 0;
  std::size_t last = 0;
  int max_change_mm = 0;
  bool operator==(const SegmentRange&) const = default;
};

struct ContourChange {
  int pair = 1;  // 1..4
  ContourKind contour = ContourKind::kProtective;
  std::vector<SegmentRange> ranges;  // ascending, never empty
  bool operator==(const ContourChange&) const = default;
};

struct ParameterDiff {
  std::vector<ValueChange> identity;  // device-owned (kept on a download)
  std::vector<ValueChange> options;
  std::vector<int> passwords_changed;   // user password numbers, 1-based
  std::vector<ContourChange> contours;  // pair by pair, protective before warning
  [[nodiscard]] bool empty() const {
    return identity.empty() && options.empty() && passwords_changed.empty() && contours.empty();
  }
};

ParameterDiff diff(const scanner::ParameterSet& old_set, const scanner::ParameterSet& new_set);

// One line per change, e.g. "pair 2 protective: segments 100-140 changed, max +350 mm";
// "no differences\n" when empty.
std::string render_text(const ParameterDiff& d);
// {"identical":false,"identity":[{"field":..,"old":..,"new":..}],"options":[...],
//  "passwords_changed":[1],"contours":[{"pair":2,"contour":"protective",
//  "ranges":[{"first":100,"last":140,"max_change_mm":350}]}]} (one line).
std::string render_json(const ParameterDiff& d);

}  // namespace rs4sim::rs4::report
