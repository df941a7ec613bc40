#pragma once
// Field evaluation of one scan against one field pair ([RS4 manual §2.3, §2.4, §5.2.3.4]).
// Segment n violates a field when an echo lies closer than the field boundary:
// contour[n] != kNoEchoMm and contour[n] < field[n] (a field value of 0 = no field
// there). One violated segment suffices (the model has no minimum object size).

#include "rs4/scanner/geometry.h"
#include "rs4/scanner/parameter_set.h"

namespace rs4sim::rs4::scanner {

struct FieldFlags {
  SegmentFlags protective;  // per segment: protective field violated
  SegmentFlags warning;     // per segment: warning field violated
  [[nodiscard]] bool protective_violated() const noexcept { return protective.any(); }
  [[nodiscard]] bool warning_violated() const noexcept { return warning.any(); }
};

FieldFlags evaluate(const Contour& contour, const FieldPair& pair) noexcept;

}  // namespace rs4sim::rs4::scanner
