#include "gridscan/scene.h"

#include <algorithm>

namespace rs4sim::gridscan {
namespace {

unsigned door_of(const Scene& s, unsigned elements) { return std::min(s.door_position, elements); }

std::uint8_t reported_door(const Scene& s, unsigned elements, Configuration c) {
  if (c == Configuration::kStatic) return kDoorPositionStatic;
  return static_cast<std::uint8_t>(door_of(s, elements));
}

}  // namespace

std::uint64_t raw_elements(const Scene& s, unsigned elements, Configuration c) {
  const std::uint64_t all = element_mask(elements);
  std::uint64_t raw = s.blocked & all;
  if (c == Configuration::kBlanking) raw |= all & ~element_mask(door_of(s, elements));
  return raw;
}

bool interrupted_below_edge(const Scene& s, unsigned elements, Configuration c) {
  const unsigned active = c == Configuration::kStatic ? elements : door_of(s, elements);
  return (s.blocked & element_mask(active)) != 0;
}

StateReport report_of(const Scene& s, unsigned elements, Configuration c) {
  StateReport r;
  r.door_position = reported_door(s, elements, c);
  r.interrupted = interrupted_below_edge(s, elements, c);
  r.internal_failure = s.internal_failure;
  r.maintenance = static_cast<std::uint8_t>(s.soiling & 0x03U);
  r.elements = raw_elements(s, elements, c);
  return r;
}

StateReport all_interrupted_report(const Scene& s, unsigned elements, Configuration c) {
  StateReport r = report_of(s, elements, c);
  r.interrupted = true;
  r.elements = element_mask(elements);
  return r;
}

}  // namespace rs4sim::gridscan
