#pragma once
// The Polaris model families and their beam counts [Polaris manual §1.2]: the body height
// h (mm) comes in fixed steps, and each family turns it into a beam count by its formula.
// "Interpolated" families (PLi) read crossed beams in the centre zone: 2N-1 points.

#include <cstdint>
#include <optional>
#include <string_view>

namespace rs4sim::polaris {

enum class Family : std::uint8_t { kPli02, kPli05, kPli12, kPl10, kPl24, kPl48 };

// "PLi02", "PLi05", "PLi12", "PL10", "PL24", "PL48".
[[nodiscard]] std::string_view to_string(Family f) noexcept;
[[nodiscard]] std::optional<Family> parse_family(std::string_view text) noexcept;

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
