#pragma once
// The Polaris model families and their beam counts [Polaris manual §1.2]: the body height
// h (mm) comes in fixed steps, and each family turns it into a beam count by its formula.
// "Interpolated" families (PLi) read crossed beams in the centre zone: 2N-1 points.
// Every model is a row of the manual's tables [Polaris manual §2.1, §2.2], with its two
// maximum response times.

#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace rs4sim::polaris {

enum class Family : std::uint8_t { kPli02, kPli05, kPli12, kPl10, kPl24, kPl48 };

// "PLi02", "PLi05", "PLi12", "PL10", "PL24", "PL48".
[[nodiscard]] std::string_view to_string(Family f) noexcept;
[[nodiscard]] std::optional<Family> parse_family(std::string_view text) noexcept;

// One row of a family's model table [Polaris manual §2.1, §2.2]. The two response-time
// columns' headers are garbled in the manual we have; the first one is the default scan
// time ([docs/decisions.md#polaris-response-time]).
struct Model {
  std::uint16_t h_mm = 0;               // body height
  std::uint16_t beams = 0;              // the table's last column
  std::uint16_t response_01ms = 0;      // first maximum response time, in 0.1 ms
  std::uint16_t response_2nd_01ms = 0;  // second maximum response time, in 0.1 ms

  [[nodiscard]] constexpr std::chrono::microseconds response_time() const noexcept {
    return std::chrono::microseconds(100 * response_01ms);
  }
  [[nodiscard]] constexpr std::chrono::microseconds response_time_2nd() const noexcept {
    return std::chrono::microseconds(100 * response_2nd_01ms);
  }
};

// The family's models by ascending height (and beam count).
[[nodiscard]] std::span<const Model> models(Family f) noexcept;

// The family's model with `beams` beams; nullptr when there is none.
[[nodiscard]] const Model* find_model(Family f, std::uint16_t beams) noexcept;

// Beam count of a family's model of body height h; nullopt when the family makes no model
// of that height. PLi 02: (h-20)/2.5-1, PLi 05: (h-20)/5-1, PLi 12: 2(h-20)/24-1,
// PL 10: (h-20)/10, PL 24: (h-20)/24, PL 48: (h-20)/48.
[[nodiscard]] std::optional<std::uint16_t> beams_for_height(Family f, std::uint16_t h_mm) noexcept;

// The body height of the family's model with `beams` beams; nullopt when there is none.
[[nodiscard]] std::optional<std::uint16_t> height_for_beams(Family f, std::uint16_t beams) noexcept;

// The smallest and largest beam count of the family (for messages).
struct BeamRange {
  std::uint16_t min = 0;
  std::uint16_t max = 0;
};
[[nodiscard]] BeamRange beam_range(Family f) noexcept;

}  // namespace rs4sim::polaris
