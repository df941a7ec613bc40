#pragma once
// Scan geometry of the RS4 ([RS4 manual §2.3]): one revolution is a
// contour of 529 distances, segment n lies at −5.04° + n·0.36° (segment 14 = 0°,
// segment 264 = 90°, segment 528 = 185.04°).
//
// Scanner coordinates (project convention, docs/rs4-scanner.md): millimetres, origin on
// the rotation axis, +x along 0° (segment 14), +y along 90° (segment 264, the middle of
// the scanned sector, "straight ahead"). Angles grow counter-clockwise from +x, so a
// beam at angle θ points along (cos θ, sin θ).

#include <array>
#include <bitset>
#include <cstddef>
#include <cstdint>

namespace rs4sim::rs4::scanner {

inline constexpr std::size_t kSegmentCount = 529;
inline constexpr double kFirstSegmentDeg = -5.04;
inline constexpr double kSegmentStepDeg = 0.36;

// Distance value of a beam that saw no echo within the modelled range. Even, so that
// bit 0 stays free for the measurement telegram's field-violation flag ([RS4 manual §5.2.3.4]).
inline constexpr std::uint16_t kNoEchoMm = 0xFFFE;

// Protective field limit ([RS4 manual §2.3, §2.4]: max 4 m) and warning field limit (project
// decision, docs/rs4-scanner.md: 15 m).
inline constexpr std::uint16_t kMaxProtectiveMm = 4000;
inline constexpr std::uint16_t kMaxWarningMm = 15000;

using Contour = std::array<std::uint16_t, kSegmentCount>;  // mm per segment
using SegmentFlags = std::bitset<kSegmentCount>;

// Angle of segment n in degrees (n in 0..528).
constexpr double segment_angle_deg(std::size_t n) noexcept {
  return kFirstSegmentDeg + static_cast<double>(n) * kSegmentStepDeg;
}

// Unit direction of every beam, computed once.
struct BeamTable {
  std::array<double, kSegmentCount> cos{};
  std::array<double, kSegmentCount> sin{};
};
const BeamTable& beam_table() noexcept;

}  // namespace rs4sim::rs4::scanner
