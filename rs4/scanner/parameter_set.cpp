#include "rs4/scanner/parameter_set.h"

#include <algorithm>

namespace rs4sim::rs4::scanner {
namespace {

using Issue = std::optional<ValidationIssue>;

Issue issue(ParameterError e, std::string_view field, std::uint32_t value, std::uint32_t limit,
            int pair = 0, int segment = -1) {
  return ValidationIssue{e, field, pair, segment, value, limit};
}

Issue check_modes(const ParameterSet& s) {
  if (s.response_steps > kMaxResponseSteps) {
    return issue(ParameterError::kResponseTimeSteps, "response_steps", s.response_steps,
                 kMaxResponseSteps);
  }
  const auto mode = static_cast<std::uint8_t>(s.restart_mode);
  if (mode > static_cast<std::uint8_t>(RestartMode::kStartRestartInterlock)) {
    return issue(ParameterError::kRestartMode, "restart_mode", mode, 2);
  }
  if (s.start_pair < 1 || s.start_pair > kFieldPairCount) {
    return issue(ParameterError::kStartPair, "start_pair", s.start_pair, kFieldPairCount);
  }
  for (std::uint8_t p = 1; p <= kFieldPairCount; ++p) {
    if (s.permitted[p - 1U] > 0x0F || !permits(s, p, p)) {
      return issue(ParameterError::kTransitionDiagonal, "permitted", s.permitted[p - 1U], 0x0F, p);
    }
  }
  if ((s.warning_output & ~kWarningSourceMask) != 0) {
    return issue(ParameterError::kWarningOutput, "warning_output", s.warning_output,
                 kWarningSourceMask);
  }
  return std::nullopt;
}

Issue check_measurement(const MeasurementOutput& m) {
  if (m.resolution == 0)
    return issue(ParameterError::kMeasurementResolution, "measurement.resolution", 0, 1);
  if (m.stop > kSegmentCount - 1) {
    return issue(ParameterError::kMeasurementRange, "measurement.stop", m.stop, kSegmentCount - 1);
  }
  if (m.start > m.stop)
    return issue(ParameterError::kMeasurementRange, "measurement.start", m.start, m.stop);
  return std::nullopt;
}

Issue check_password(const Password& pw, int index) {
  bool padding = false;
  for (std::size_t i = 0; i < pw.size(); ++i) {
    const std::uint8_t b = pw[i];
    if (b == 0xFF) {
      padding = true;
      continue;
    }
    if (padding || b < 0x20 || b > 0x7E) {
      return issue(ParameterError::kPassword, "passwords[]", b, 0x7E, index, static_cast<int>(i));
    }
  }
  return std::nullopt;
}

Issue check_pair(const FieldPair& fp, int pair) {
  for (std::size_t n = 0; n < kSegmentCount; ++n) {
    if (fp.protective_mm[n] > kMaxProtectiveMm) {
      return issue(ParameterError::kProtectiveTooFar, "pairs[].protective_mm", fp.protective_mm[n],
                   kMaxProtectiveMm, pair, static_cast<int>(n));
    }
    if (fp.warning_mm[n] > kMaxWarningMm) {
      return issue(ParameterError::kWarningTooFar, "pairs[].warning_mm", fp.warning_mm[n],
                   kMaxWarningMm, pair, static_cast<int>(n));
    }
  }
  return std::nullopt;
}

}  // namespace

ParameterSet factory_default() {
  ParameterSet s;
  s.identity = Identity{0, 0x0004, 1, 0};
  s.response_steps = 0;
  s.restart_mode = RestartMode::kStartRestartInterlock;
  s.start_pair = 1;
  s.permitted.fill(0x0F);
  s.warning_output = kWarnOnContamination;
  s.measurement = MeasurementOutput{1, 0, kSegmentCount - 1};
  for (auto& pw : s.passwords) pw.fill(0xFF);
  for (std::size_t p = 0; p < kFieldPairCount; ++p) {
    const auto protective = static_cast<std::uint16_t>(1000 + 500 * p);
    s.pairs[p].protective_mm.fill(protective);
    s.pairs[p].warning_mm.fill(static_cast<std::uint16_t>(protective + 1000));
  }
  return s;
}

std::optional<ValidationIssue> validate(const ParameterSet& set) {
  if (Issue i = check_modes(set)) return i;
  if (Issue i = check_measurement(set.measurement)) return i;
  for (std::size_t k = 0; k < set.passwords.size(); ++k) {
    if (Issue i = check_password(set.passwords[k], static_cast<int>(k + 1))) return i;
  }
  for (std::size_t p = 0; p < kFieldPairCount; ++p) {
    if (Issue i = check_pair(set.pairs[p], static_cast<int>(p + 1))) return i;
  }
  const auto& start = set.pairs[set.start_pair - 1U].protective_mm;
  if (std::all_of(start.begin(), start.end(), [](std::uint16_t v) { return v == 0; })) {
    return issue(ParameterError::kEmptyStartField, "pairs[].protective_mm", 0, 1, set.start_pair);
  }
  return std::nullopt;
}

std::string ValidationIssue::message() const {
  std::string m = make_error_code(error).message();
  m += " (field " + std::string(field);
  if (pair != 0) m += ", pair/index " + std::to_string(pair);
  if (segment >= 0) m += ", segment/byte " + std::to_string(segment);
  m += ", value " + std::to_string(value) + ", limit " + std::to_string(limit) + ")";
  return m;
}

std::chrono::milliseconds response_time(const ParameterSet& set) {
  return std::chrono::milliseconds(80 + 40 * static_cast<int>(set.response_steps));
}

std::uint32_t scans_to_switch_off(const ParameterSet& set) { return 2U + set.response_steps; }

ParameterSet merge_download(const ParameterSet& device, const ParameterSet& incoming) {
  ParameterSet merged = incoming;
  merged.passwords = device.passwords;
  merged.identity = device.identity;
  return merged;
}

}  // namespace rs4sim::rs4::scanner
