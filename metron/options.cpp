#include "metron/options.h"

#include "metron/enum_table.h"

#include <algorithm>
#include <array>

namespace rs4sim::metron {
namespace {

using std::chrono::milliseconds;

constexpr std::array<std::string_view, 2> kLineModes{"standard", "slave"};
constexpr std::array<std::string_view, 3> kFormats{"binary", "hex", "decimal"};
constexpr std::array<std::string_view, 5> kReportingModes{"continuous", "periodical", "on-request",
                                                          "status-change", "input-related"};
constexpr std::array<std::string_view, 7> kInputTypes{
    "no-function",    "enable-line",  "enable-all", "start-stop-line",
    "start-stop-all", "line-standby", "all-standby"};

bool is_start_stop(InputType t) {
  return t == InputType::kStartStopLine || t == InputType::kStartStopAll;
}

std::string validate_standard(const Options& o) {
  if (o.baud < 1200 || o.baud > 115200) return "baud must be 1200..115200";
  if (o.report.empty()) return "the report needs at least one measurement";
  if (o.report.size() > 16) return "the report takes at most 16 measurements";
  if (o.reporting_mode == ReportingMode::kPeriodical && !is_listed_period(o.period))
    return "period must be one of 50, 100, 250, 500, 750 ms, 1, 1.25, 1.5, 2, 3 s";
  if (o.reporting_mode == ReportingMode::kInputRelated && is_start_stop(o.input_type) &&
      o.report.size() != 1)
    return "input type start-stop needs exactly one report measurement";
  return {};
}

}  // namespace

std::string Options::validate() const {
  if (beams < 1 || beams > kMaxBeams) return "beams must be 1..255";
  if (node_enabled && node == kBroadcast) return "node must be 0..254 (255 is broadcast)";
  if (scan_cycle < milliseconds(1) || scan_cycle > milliseconds(1000))
    return "scan cycle must be 1..1000 ms";
  if (t_response < milliseconds(1) || t_response > milliseconds(2000))
    return "t_response must be 1..2000 ms";
  if (receive_timeout < milliseconds(1)) return "receive timeout must be at least 1 ms";
  for (const auto b : blocked) {
    if (b < 1 || b > beams)
      return "blocked beam " + std::to_string(b) + " outside 1.." + std::to_string(beams);
  }
  if (auto w = metron::validate(wire); !w.empty()) return w;
  if (line_mode == LineMode::kStandard) return validate_standard(*this);
  return {};
}

stream::LineSettings line_settings(const Options& o) {
  if (o.line_mode == LineMode::kSlave) return {19200, 8, stream::Parity::kEven, 1};
  return {o.baud, 8, o.parity, 1};
}

bool is_listed_period(stream::Duration period) {
  constexpr std::array<milliseconds, 10> kPeriods{
      milliseconds(50),   milliseconds(100),  milliseconds(250),  milliseconds(500),
      milliseconds(750),  milliseconds(1000), milliseconds(1250), milliseconds(1500),
      milliseconds(2000), milliseconds(3000)};
  return std::find(kPeriods.begin(), kPeriods.end(), period) != kPeriods.end();
}

std::string_view to_string(LineMode m) { return kLineModes[static_cast<std::size_t>(m)]; }
std::string_view to_string(Format f) { return kFormats[static_cast<std::size_t>(f)]; }
std::string_view to_string(ReportingMode m) { return kReportingModes[static_cast<std::size_t>(m)]; }
std::string_view to_string(InputType t) { return kInputTypes[static_cast<std::size_t>(t)]; }

std::optional<LineMode> parse_line_mode(std::string_view s) {
  return enum_of_entry<LineMode>(kLineModes, s);
}
std::optional<Format> parse_format(std::string_view s) {
  return enum_of_entry<Format>(kFormats, s);
}
std::optional<ReportingMode> parse_reporting_mode(std::string_view s) {
  return enum_of_entry<ReportingMode>(kReportingModes, s);
}
std::optional<InputType> parse_input_type(std::string_view s) {
  return enum_of_entry<InputType>(kInputTypes, s);
}

}  // namespace rs4sim::metron
