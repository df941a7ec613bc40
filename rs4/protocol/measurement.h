#pragma once
// COM_CMD_MESS_16_RT 0x23, the measurement telegram ([RS4 manual §5.2.3.4];
// [RS4 manual §5.2.3.4], table 5.2-14). Data after the options:
//   scan number  8 bytes  b31..24 FE b23..16 FE b15..8 FE b7..0 FE
//   resolution   1 byte   segments between two output values (≥ 1)
//   start        2 bytes  first segment output (0..528)
//   stop         2 bytes  last segment output (0..528), always output
//   values       2 bytes each, segments start, start+res, …, stop: distance in mm,
//                bit 0 = a protective field was violated since the previous value
// All 2-byte values high byte first.

#include "rs4/protocol/errors.h"
#include "rs4/protocol/option_bytes.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rs4sim::rs4::protocol {

inline constexpr std::size_t kContourSegments = 529;  // -5.04° … 185.04° in 0.36° steps
inline constexpr std::uint16_t kMaxSegment = 528;
inline constexpr std::uint8_t kScanNumberFiller = 0xFE;
inline constexpr std::size_t kMeasurementHeaderSize = 8 + 1 + 2 + 2;  // before the values

// A value: distance with bit 0 replaced by the protective-field violation flag.
constexpr std::uint16_t measurement_value(std::uint16_t distance_mm, bool violated) noexcept {
  return static_cast<std::uint16_t>((distance_mm & 0xFFFEU) | (violated ? 1U : 0U));
}
constexpr std::uint16_t value_distance_mm(std::uint16_t value) noexcept {
  return static_cast<std::uint16_t>(value & 0xFFFEU);
}
constexpr bool value_field_violated(std::uint16_t value) noexcept { return (value & 1U) != 0; }

// Number of values for a window, or kBadResolution / kSegmentOutOfRange /
// kStartAfterStop. Example [RS4 manual §5.2.3.4]: start 0, stop 528, resolution 4 → 133.
Result<std::size_t> measurement_value_count(std::uint16_t start, std::uint16_t stop,
                                            std::uint8_t resolution) noexcept;

struct MeasurementTelegram {
  TelegramPrefix prefix;
  std::uint32_t scan_number = 0;
  std::uint8_t resolution = 1;
  std::uint16_t start = 0;
  std::uint16_t stop = kMaxSegment;
  std::vector<std::uint16_t> values;  // already carrying the bit-0 flags
  friend bool operator==(const MeasurementTelegram&, const MeasurementTelegram&) = default;
};

// Appends the data part (scan number … values) of a telegram whose values are given.
std::error_code encode_measurement_data(const MeasurementTelegram& telegram,
                                        std::vector<std::uint8_t>& out);
// Appends the data part picking the values from a full 529-segment contour (the
// scanner model's output): segments start, start+res, …, stop.
std::error_code encode_measurement_data(std::uint32_t scan_number, std::uint8_t resolution,
                                        std::uint16_t start, std::uint16_t stop,
                                        std::span<const std::uint16_t, kContourSegments> contour,
                                        std::vector<std::uint8_t>& out);
// Parses the data part into telegram (scan number … values).
std::error_code decode_measurement_data(std::span<const std::uint8_t> data,
                                        MeasurementTelegram& telegram);

}  // namespace rs4sim::rs4::protocol
