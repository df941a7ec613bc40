#include "polaris/model.h"

#include <array>

namespace rs4sim::polaris {

namespace {

// Heights h_min..h_max in steps of `step`; PLi 05 and PL 10 step by 20 mm up to 340 mm
// first; PL 10 has one model off the steps, PL 10-500 (h 520 mm, 50 beams). The PL 10 table
// [Polaris manual §2.2]: PL 10-80 … 10-320 in 20 mm steps, then 10-400, 10-480, 10-500,
// 10-560 … 10-3440 in 80 mm steps.
struct HeightSteps {
  Family family;
  std::string_view name;
  std::uint16_t h_min;
  std::uint16_t h_max;
  std::uint16_t step;
  std::uint16_t fine_until;  // 0: no fine steps
  std::uint16_t extra = 0;   // one more model height off the steps; 0: none
};

constexpr std::uint16_t kFineStep = 20;

constexpr std::array<HeightSteps, 6> kFamilies{{
    {Family::kPli02, "PLi02", 100, 3460, 80, 0},
    {Family::kPli05, "PLi05", 100, 3460, 80, 340},
    {Family::kPli12, "PLi12", 116, 3476, 96, 0},
    {Family::kPl10, "PL10", 100, 3460, 80, 340, 520},
    {Family::kPl24, "PL24", 116, 3476, 96, 0},
    {Family::kPl48, "PL48", 212, 2900, 192, 0},
}};

const HeightSteps& steps_of(Family f) noexcept {
  for (const HeightSteps& s : kFamilies) {
    if (s.family == f) return s;
  }
  return kFamilies[0];
}

bool is_model_height(const HeightSteps& s, std::uint16_t h) noexcept {
  if (h < s.h_min || h > s.h_max) return false;
  if (s.extra != 0 && h == s.extra) return true;
  if (s.fine_until != 0 && h <= s.fine_until) return (h - s.h_min) % kFineStep == 0;
  const std::uint16_t base = s.fine_until != 0 ? s.fine_until : s.h_min;
  return h >= base && (h - base) % s.step == 0;
}

// The formula, in integer millimetres (every model height gives a whole number).
int formula(Family f, int h) noexcept {
  const int l = h - 20;
  switch (f) {
    case Family::kPli02: return l * 2 / 5 - 1;
    case Family::kPli05: return l / 5 - 1;
    case Family::kPli12: return l / 12 - 1;
    case Family::kPl10: return l / 10;
    case Family::kPl24: return l / 24;
    case Family::kPl48: return l / 48;
  }
  return 0;
}

}  // namespace

std::string_view to_string(Family f) noexcept { return steps_of(f).name; }

std::optional<Family> parse_family(std::string_view text) noexcept {
  for (const HeightSteps& s : kFamilies) {
    if (s.name == text) return s.family;
  }
  return std::nullopt;
}

std::optional<std::uint16_t> beams_for_height(Family f, std::uint16_t h_mm) noexcept {
  if (!is_model_height(steps_of(f), h_mm)) return std::nullopt;
  return static_cast<std::uint16_t>(formula(f, h_mm));
}

std::optional<std::uint16_t> height_for_beams(Family f, std::uint16_t beams) noexcept {
  const HeightSteps& s = steps_of(f);
  for (int h = s.h_min; h <= s.h_max; ++h) {
    const auto height = static_cast<std::uint16_t>(h);
    if (is_model_height(s, height) && formula(f, h) == beams) return height;
  }
  return std::nullopt;
}

BeamRange beam_range(Family f) noexcept {
  const HeightSteps& s = steps_of(f);
  return {static_cast<std::uint16_t>(formula(f, s.h_min)),
          static_cast<std::uint16_t>(formula(f, s.h_max))};
}

}  // namespace rs4sim::polaris
