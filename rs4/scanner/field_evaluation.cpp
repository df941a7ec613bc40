#include "rs4/scanner/field_evaluation.h"

namespace rs4sim::rs4::scanner {

FieldFlags evaluate(const Contour& contour, const FieldPair& pair) noexcept {
  FieldFlags f;
  for (std::size_t n = 0; n < kSegmentCount; ++n) {
    const std::uint16_t d = contour[n];
    if (d == kNoEchoMm) continue;
    if (d < pair.protective_mm[n]) f.protective.set(n);
    if (d < pair.warning_mm[n]) f.warning.set(n);
  }
  return f;
}

}  // namespace rs4sim::rs4::scanner
