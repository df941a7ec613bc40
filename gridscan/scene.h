#pragma once
// The door-blanking model of the curtain ([GridScan manual §6.1, §9.2.4]): what the
// elements see and what the state bytes report.
//
// A closing door cuts the beams from the top element downwards; the door position is the
// number of elements below its lower edge, i.e. the elements left active (N = fully open,
// 0 = closed; DECISION, docs/gridscan.md). In blanking mode only elements 1..door position
// count for the "interrupted" bit 8; in static mode there is no door (position 255) and
// every element counts. The element bitmap of Full state is the raw per-element state:
// elements covered by the door show interrupted (DECISION).

#include "codec/error_category.h"
#include "gridscan/payload.h"

#include <cstdint>
#include <span>
#include <string_view>
#include <system_error>
#include <vector>

namespace rs4sim::gridscan {

// Why a scene change was refused (the same shape as metron::SceneError, polaris::SceneError).
enum class SceneError : std::uint8_t {
  kNoSuchElement = 1,  // an element number outside 1..elements
};
[[nodiscard]] std::string_view to_string(SceneError e) noexcept;
[[nodiscard]] constexpr const char* error_category_name(SceneError) noexcept {
  return "gridscan.scene";
}
[[nodiscard]] inline std::error_code make_error_code(SceneError e) noexcept {
  return codec::make_error_code_of(e);
}

struct Scene {
  unsigned door_position = 0;     // 0..N; N = door open
  std::uint64_t blocked = 0;      // bit e-1 = element e interrupted by an object
  std::uint8_t soiling = 0;       // maintenance level 0..3
  bool internal_failure = false;  // bit 9 ([GridScan manual §10.2.3])
  std::uint16_t alignment_value = 0;

  // The objects as element numbers, the form every device's scene takes (metron/scene.h,
  // polaris/scene.h): `elements` interrupted, the others free. An element outside 1..count
  // is SceneError::kNoSuchElement and changes nothing.
  std::error_code set_interrupted(std::span<const std::uint16_t> elements, unsigned count);
  // The elements interrupted by objects, ascending (the door's cover is not an object).
  [[nodiscard]] std::vector<std::uint16_t> interrupted() const;
};

// Bits of elements 1..n.
[[nodiscard]] constexpr std::uint64_t element_mask(unsigned n) noexcept {
  return n >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << n) - 1U;
}

// The elements of `mask` among 1..count, ascending.
[[nodiscard]] std::vector<std::uint16_t> elements_of(std::uint64_t mask, unsigned count);

// What the elements see: the objects, plus the door's cover in blanking mode.
[[nodiscard]] std::uint64_t raw_elements(const Scene& s, unsigned elements, Configuration c);

// Bit 8: an element below the door edge (any element in static mode) is interrupted.
[[nodiscard]] bool interrupted_below_edge(const Scene& s, unsigned elements, Configuration c);

// The state bytes in normal operation.
[[nodiscard]] StateReport report_of(const Scene& s, unsigned elements, Configuration c);

// The state bytes when every element shows interrupted: stand-by
// ([GridScan manual §10.1.1]) and the first message after a test
// ([GridScan manual §10.1.2]).
[[nodiscard]] StateReport all_interrupted_report(const Scene& s, unsigned elements,
                                                 Configuration c);

}  // namespace rs4sim::gridscan
