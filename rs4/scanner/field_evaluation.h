#pragma once
// Field evaluation of one scan against one field pair ([RS4 manual §2.3, §2.4, §5.2.3.4]).
// Segment n violates a field when an echo lies closer than the field boundary:
// contour[n] != kNoEchoMm and contour[n] < field[n] (a field value of 0 = no field
// there). One violated segment suffices (the model has no minimum object size).

#include "rs4/scanner/geometry.h"
#include "rs4/scanner/parameter_set.h"
#include "rs4/scanner/scene.h"

#include <optional>

namespace rs4sim::rs4::scanner {

struct FieldFlags {
  SegmentFlags protective;  // per segment: protective field violated
  SegmentFlags warning;     // per segment: warning field violated
  [[nodiscard]] bool protective_violated() const noexcept { return protective.any(); }
  [[nodiscard]] bool warning_violated() const noexcept { return warning.any(); }
};

FieldFlags evaluate(const Contour& contour, const FieldPair& pair) noexcept;

// A narrow obstacle that violates the pair's protective field (warning = false) or only its
// warning field (warning = true): three beams around the segment with the most room, at half
// the protective distance, or halfway between the protective and the warning boundary
// (Device.ViolateField, docs/rpc.md). nullopt when the pair has no such field, or less than
// 20 mm of it anywhere.
std::optional<RawContour> field_violation(const FieldPair& pair, bool warning);

}  // namespace rs4sim::rs4::scanner
