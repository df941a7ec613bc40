#pragma once
// What the barrier sees: which of its beams are interrupted, counted physically from the
// connector cap (beam 1) [Polaris manual §7.4.2 "Scan direction"]; the scan direction only
// changes the numbers the barrier transmits (polaris/data_modes.h).

#include <cstdint>
#include <span>
#include <system_error>
#include <vector>

namespace rs4sim::polaris {

class Scene {
 public:
  explicit Scene(std::uint16_t beams) : interrupted_(beams, 0) {}

  [[nodiscard]] std::uint16_t beams() const {
    return static_cast<std::uint16_t>(interrupted_.size());
  }
  // Exactly `beams` (physical, 1-based) interrupted from now on; errc::invalid_argument and
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
