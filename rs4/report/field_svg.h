#pragma once
// SVG pictures of the RS4 field pairs, for an engineer who compares fields by looking at
// them: one panel per pair in polar view around the scanner, the protective contour
// filled red, the warning contour as an orange outline, distance rings with labels. In a
// diff picture the old set is drawn over the new one as dashed grey outlines, with a legend.
//
// Geometry [RS4 manual §2.3] [docs/rs4-scanner.md §1]: segment n of 529 lies at
// −5.04° + n·0.36° (segment 0 = −5.04°, segment 264 = 90° = straight ahead, segment 528 =
// 185.04°); angles counter-clockwise from +x. The picture puts 90° up, so +x points right.
// A segment's value is its distance in mm; 0 ("no field") is drawn at the origin.
//
// Deterministic: fixed layout, coordinates with one decimal ("%.1f", C locale), so the
// same sets give the same bytes. Every text is XML-escaped.

#include "rs4/scanner/parameter_set.h"

#include <string>
#include <string_view>

namespace rs4sim::rs4::report {

// `title` is printed on top (e.g. "station default/4, version 7").
std::string field_svg(const scanner::ParameterSet& set, std::string_view title);

struct DiffLabels {
  std::string_view title;
  std::string_view old_label;  // legend text of the old set, e.g. "version 3"
  std::string_view new_label;
};
std::string field_diff_svg(const scanner::ParameterSet& old_set,
                           const scanner::ParameterSet& new_set, const DiffLabels& labels);

// `text` with & < > " ' replaced by their XML entities.
std::string xml_escape(std::string_view text);

}  // namespace rs4sim::rs4::report
