#pragma once
// The RS4 parameter set — EXTENSION ([docs/decisions.md#rs4-extensions]: RS4soft's format is not
// public; the project defines this set and documents it in docs/rs4-scanner.md).
// Manual facts it follows: 4 field pairs of protective (≤4 m) + warning field
// ([RS4 manual §2.3, §2.4]), response time 80 ms + n·40 ms ([RS4 manual §6.6], "minimal 80 ms,
// einstellbar in 40 ms Schritten"), start/restart interlock ([RS4 manual §4.3]), permitted
// field-pair transitions and the pair allowed at switch-on ([RS4 manual §5.1.2]), warning output
// assignment ([RS4 manual §5.1.1]), measurement output resolution/start/stop
// ([RS4 manual §5.2.3.4]), user passwords that a proxy download never overwrites
// ([RS4 manual §7.2.4]).

#include "rs4/scanner/errors.h"
#include "rs4/scanner/geometry.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace rs4sim::rs4::scanner {

inline constexpr std::size_t kFieldPairCount = 4;
inline constexpr std::uint8_t kMaxResponseSteps = 14;  // T ≤ 80 + 14·40 = 640 ms
inline constexpr std::size_t kPasswordLength = 8;      // ASCII, 0xFF-padded
                                                       // ([roboticslibrary/rl LeuzeRs4.cpp])
inline constexpr std::size_t kUserPasswordCount = 2;

struct FieldPair {
  Contour protective_mm{};  // 0 = no protective field on that segment
  Contour warning_mm{};     // 0 = no warning field on that segment
  bool operator==(const FieldPair&) const = default;
};

enum class RestartMode : std::uint8_t {
  kAutomatic = 0,              // no interlock: OSSD on again once the field is free
  kStartInterlock = 1,         // restart pulse needed after power-up / fault acknowledge
  kStartRestartInterlock = 2,  // ... and after every protective-field violation
};

// Warning output assignment, bit mask ([RS4 manual §5.1.1] recommends window contamination).
enum WarningSource : std::uint8_t {
  kWarnOnContamination = 0x01,     // window contamination at or above the warning level
  kWarnOnWarningField = 0x02,      // the active warning field is violated
  kWarnOnFault = 0x04,             // the scanner is in its error state
  kWarnOnRestartInterlock = 0x08,  // the restart interlock waits for a pulse
};
inline constexpr std::uint8_t kWarningSourceMask = 0x0F;

struct MeasurementOutput {  // [RS4 manual §5.2.3.4] (table 5.2-14): resolution, start, stop
  std::uint8_t resolution = 1;
  std::uint16_t start = 0;
  std::uint16_t stop = kSegmentCount - 1;
  bool operator==(const MeasurementOutput&) const = default;
};

struct Identity {  // device-owned, kept on a download (docs/rs4-scanner.md)
  std::uint32_t serial_number = 0;
  std::uint16_t device_type = 0;
  std::uint8_t firmware_major = 0;
  std::uint8_t firmware_minor = 0;
  bool operator==(const Identity&) const = default;
};

using Password = std::array<std::uint8_t, kPasswordLength>;

struct ParameterSet {
  Identity identity;
  std::uint8_t response_steps = 0;  // n in T = 80 ms + n·40 ms
  RestartMode restart_mode = RestartMode::kStartRestartInterlock;
  std::uint8_t start_pair = 1;  // 1..4
  // permitted[from-1] bit (to-1): switching from `from` to `to` is allowed.
  std::array<std::uint8_t, kFieldPairCount> permitted{};
  std::uint8_t warning_output = kWarnOnContamination;
  MeasurementOutput measurement;
  std::array<Password, kUserPasswordCount> passwords{};
  std::array<FieldPair, kFieldPairCount> pairs{};
  bool operator==(const ParameterSet&) const = default;
};

// The project's factory setting (docs/rs4-scanner.md "Factory default").
ParameterSet factory_default();

// A field that failed validation: what, where, which limit.
struct ValidationIssue {
  ParameterError error{};
  std::string_view field;   // e.g. "pairs[].protective_mm"
  int pair = 0;             // 1..4 when the issue concerns a pair, else 0
  int segment = -1;         // 0..528 when it concerns a segment, else -1
  std::uint32_t value = 0;  // the offending value
  std::uint32_t limit = 0;  // the limit it broke
  [[nodiscard]] std::string message() const;
};

// First issue in a fixed order (identity, timing, modes, transitions, outputs,
// passwords, pairs in order, segments in order); nullopt when the set is valid.
std::optional<ValidationIssue> validate(const ParameterSet& set);

[[nodiscard]] constexpr bool permits(const ParameterSet& set, std::uint8_t from, std::uint8_t to) {
  return from >= 1 && from <= kFieldPairCount && to >= 1 && to <= kFieldPairCount &&
         (set.permitted[from - 1U] & (1U << (to - 1U))) != 0;
}

// Response time T = 80 ms + n·40 ms ([RS4 manual §6.6]) and the number of consecutive violated
// 40 ms scans that switch the OSSDs off (T / 40 ms, docs/rs4-scanner.md "OSSD model").
std::chrono::milliseconds response_time(const ParameterSet& set);
std::uint32_t scans_to_switch_off(const ParameterSet& set);

// What a download keeps from the device ([RS4 manual §7.2.4]: user passwords are never overwritten
// by a proxy download; identity belongs to the device): `incoming` with `device`'s
// passwords and identity.
ParameterSet merge_download(const ParameterSet& device, const ParameterSet& incoming);

}  // namespace rs4sim::rs4::scanner
