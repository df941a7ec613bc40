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

std::vector<std::uint16_t> elements_of(std::uint64_t mask, unsigned count) {
  std::vector<std::uint16_t> out;
  for (unsigned e = 1; e <= std::min(count, 64U); ++e) {
    if ((mask >> (e - 1U) & 1U) != 0) out.push_back(static_cast<std::uint16_t>(e));
  }
  return out;
}

std::string_view to_string(SceneError e) noexcept {
  switch (e) {
    case SceneError::kNoSuchElement: return "no such element";
  }
  return "unknown scene error";
}

std::error_code Scene::set_interrupted(std::span<const std::uint16_t> elements, unsigned count) {
  std::uint64_t mask = 0;
  for (const std::uint16_t e : elements) {
    if (e == 0 || e > std::min(count, 64U)) return SceneError::kNoSuchElement;
    mask |= std::uint64_t{1} << (e - 1U);
  }
  blocked = mask;
  return {};
}

std::vector<std::uint16_t> Scene::interrupted() const { return elements_of(blocked, 64); }

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
