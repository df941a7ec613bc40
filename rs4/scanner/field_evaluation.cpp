#include "rs4/scanner/field_evaluation.h"

#include <algorithm>
#include <vector>

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

std::optional<RawContour> field_violation(const FieldPair& pair, bool warning) {
  std::optional<std::size_t> best;
  std::uint16_t best_mm = 0;
  for (std::size_t s = 0; s < kSegmentCount; ++s) {
    const std::uint16_t p = pair.protective_mm[s];
    const std::uint16_t w = pair.warning_mm[s];
    const std::uint16_t room = warning ? (w > p ? static_cast<std::uint16_t>(w - p) : 0) : p;
    if (room > best_mm) {
      best_mm = room;
      best = s;
    }
  }
  if (!best || best_mm < 20) return std::nullopt;
  RawContour raw{std::vector<std::uint16_t>(kSegmentCount, kNoEchoMm)};
  const std::size_t first = *best == 0 ? 0 : *best - 1;
  const std::size_t last = std::min(*best + 1, kSegmentCount - 1);
  for (std::size_t s = first; s <= last; ++s) {
    const std::uint16_t p = pair.protective_mm[s];
    const std::uint16_t w = pair.warning_mm[s];
    if (warning && w > p + 10) raw.mm[s] = static_cast<std::uint16_t>(p + (w - p) / 2);
    if (!warning && p > 10) raw.mm[s] = static_cast<std::uint16_t>(p / 2);
  }
  return raw;
}

}  // namespace rs4sim::rs4::scanner
