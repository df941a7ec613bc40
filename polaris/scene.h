#pragma once
// What the barrier sees: which of its beams are interrupted, counted physically from the
// connector cap (beam 1) [Polaris manual §7.4.2 "Scan direction"]; the scan direction only
// changes the numbers the barrier transmits (polaris/data_modes.h).

#include "codec/error_category.h"

#include <cstdint>
#include <span>
#include <string_view>
#include <system_error>
#include <vector>

namespace rs4sim::polaris {

// Why a scene change was refused (the same shape as metron::SceneError, gridscan::SceneError).
enum class SceneError : std::uint8_t {
  kNoSuchBeam = 1,  // a beam number outside 1..beams()
};
[[nodiscard]] std::string_view to_string(SceneError e) noexcept;
[[nodiscard]] constexpr const char* error_category_name(SceneError) noexcept {
  return "polaris.scene";
}
[[nodiscard]] inline std::error_code make_error_code(SceneError e) noexcept {
  return codec::make_error_code_of(e);
}

class Scene {
 public:
  explicit Scene(std::uint16_t beams) : interrupted_(beams, 0) {}

  [[nodiscard]] std::uint16_t beams() const {
    return static_cast<std::uint16_t>(interrupted_.size());
  }
  // Exactly `beams` (physical, 1-based) interrupted from now on; SceneError::kNoSuchBeam and
  // nothing changed when one is 0 or beyond beams().
  std::error_code set_interrupted(std::span<const std::uint16_t> beams);
  // The interrupted physical beams, ascending.
  [[nodiscard]] std::vector<std::uint16_t> interrupted() const;
  [[nodiscard]] bool any_interrupted() const;
  // Per physical beam (index i = beam i+1), non-zero = interrupted: what data_modes.h reads.
  [[nodiscard]] std::span<const std::uint8_t> flags() const { return interrupted_; }

  friend bool operator==(const Scene&, const Scene&) = default;

 private:
  std::vector<std::uint8_t> interrupted_;
};

}  // namespace rs4sim::polaris

template <>
struct std::is_error_code_enum<rs4sim::polaris::SceneError> : std::true_type {};
