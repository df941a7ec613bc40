#include "rs4/scanner/measurement.h"

#include "rs4/scanner/scanner.h"

namespace rs4sim::rs4::scanner {
namespace {

std::uint16_t flagged(std::uint16_t mm, bool violated) {
  return static_cast<std::uint16_t>((mm & 0xFFFEU) | (violated ? 1U : 0U));
}

bool any_in(const SegmentFlags& f, std::size_t from, std::size_t to) {  // [from, to]
  for (std::size_t n = from; n <= to; ++n) {
    if (f.test(n)) return true;
  }
  return false;
}

}  // namespace

Contour measurement_contour(const Contour& contour, const SegmentFlags& protective,
                            const MeasurementOutput& window) noexcept {
  Contour out{};
  for (std::size_t n = 0; n < kSegmentCount; ++n) out[n] = flagged(contour[n], protective.test(n));
  if (window.resolution == 0 || window.start > window.stop || window.stop >= kSegmentCount)
    return out;
  std::size_t previous = window.start;
  for (std::size_t s = window.start; s <= window.stop; s += window.resolution) {
    const std::size_t from = s == window.start ? s : previous + 1;
    out[s] = flagged(contour[s], any_in(protective, from, s));
    previous = s;
  }
  if (previous != window.stop) {
    out[window.stop] = flagged(contour[window.stop], any_in(protective, previous + 1, window.stop));
  }
  return out;
}

Contour measurement_contour(const ScanResult& scan, const MeasurementOutput& window) noexcept {
  return measurement_contour(scan.contour, scan.first.protective | scan.second.protective, window);
}

}  // namespace rs4sim::rs4::scanner
