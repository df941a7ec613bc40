#pragma once
// Names and figures of the RS4 parameter fields as the reports show them (summary, diff,
// CLI): one spelling for each option, shared so that the summary and the diff agree.
// The fields themselves: rs4/scanner/parameter_set.h, docs/rs4-scanner.md.

#include "rs4/scanner/parameter_set.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rs4sim::rs4::report {

// "automatic", "start_interlock", "start_restart_interlock" ([RS4 manual §4.3]); "unknown(N)".
std::string restart_mode_name(scanner::RestartMode mode);
// The sources of the warning output, e.g. {"contamination", "warning_field"}
// ([RS4 manual §5.1.1]); unknown bits as "bit(N)".
std::vector<std::string> warning_output_names(std::uint8_t mask);
// The pairs reachable from `from` (1..4), ascending ([RS4 manual §5.1.2]).
std::vector<int> permitted_targets(const scanner::ParameterSet& set, std::uint8_t from);
// "1.0"
std::string firmware_text(const scanner::Identity& identity);
// Items joined by ", " ("none" when empty).
std::string join(const std::vector<std::string>& items);
std::string join(const std::vector<int>& items);

// A contour's extent over its active segments (value != 0: "0 = no field", parameter_set.h).
struct ContourStats {
  std::uint16_t min_mm = 0;  // 0 when no segment is active
  std::uint16_t max_mm = 0;
  std::size_t active_segments = 0;
};
ContourStats contour_stats(const scanner::Contour& contour);

enum class ContourKind : std::uint8_t { kProtective, kWarning };
std::string_view contour_name(ContourKind kind);  // "protective", "warning"
const scanner::Contour& contour_of(const scanner::FieldPair& pair, ContourKind kind);

}  // namespace rs4sim::rs4::report
