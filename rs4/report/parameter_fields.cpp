#include "rs4/report/parameter_fields.h"

#include <algorithm>
#include <array>

namespace rs4sim::rs4::report {

std::string restart_mode_name(scanner::RestartMode mode) {
  switch (mode) {
    case scanner::RestartMode::kAutomatic: return "automatic";
    case scanner::RestartMode::kStartInterlock: return "start_interlock";
    case scanner::RestartMode::kStartRestartInterlock: return "start_restart_interlock";
  }
  return "unknown(" + std::to_string(static_cast<unsigned>(mode)) + ")";
}

std::vector<std::string> warning_output_names(std::uint8_t mask) {
  static constexpr std::array<std::string_view, 4> kNames{"contamination", "warning_field", "fault",
                                                          "restart_interlock"};
  std::vector<std::string> names;
  for (unsigned bit = 0; bit < 8; ++bit) {
    if ((mask & (1U << bit)) == 0) continue;
    names.push_back(bit < kNames.size() ? std::string(kNames[bit])
                                        : "bit(" + std::to_string(bit) + ")");
  }
  return names;
}

std::vector<int> permitted_targets(const scanner::ParameterSet& set, std::uint8_t from) {
  std::vector<int> to;
  for (std::uint8_t p = 1; p <= scanner::kFieldPairCount; ++p) {
    if (scanner::permits(set, from, p)) to.push_back(p);
  }
  return to;
}

std::string firmware_text(const scanner::Identity& identity) {
  return std::to_string(identity.firmware_major) + "." + std::to_string(identity.firmware_minor);
}

std::string join(const std::vector<std::string>& items) {
  if (items.empty()) return "none";
  std::string out;
  for (const auto& item : items) {
    if (!out.empty()) out += ", ";
    out += item;
  }
  return out;
}

std::string join(const std::vector<int>& items) {
  std::vector<std::string> text;
  text.reserve(items.size());
  for (const int i : items) text.push_back(std::to_string(i));
  return join(text);
}

ContourStats contour_stats(const scanner::Contour& contour) {
  ContourStats s;
  for (const std::uint16_t mm : contour) {
    if (mm == 0) continue;
    s.min_mm = s.active_segments == 0 ? mm : std::min(s.min_mm, mm);
    s.max_mm = std::max(s.max_mm, mm);
    ++s.active_segments;
  }
  return s;
}

std::string_view contour_name(ContourKind kind) {
  return kind == ContourKind::kProtective ? "protective" : "warning";
}

const scanner::Contour& contour_of(const scanner::FieldPair& pair, ContourKind kind) {
  return kind == ContourKind::kProtective ? pair.protective_mm : pair.warning_mm;
}

}  // namespace rs4sim::rs4::report
