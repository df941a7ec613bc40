#include "rs4/report/parameter_summary.h"

#include "rs4/report/json_writer.h"
#include "rs4/report/parameter_fields.h"
#include "rs4/scanner/identity_text.h"

#include <cstdio>

namespace rs4sim::rs4::report {
namespace {

using scanner::ParameterSet;

void write_stats(JsonWriter& w, std::string_view name, const ContourStats& s) {
  w.key(name).begin_object();
  w.field("min_mm", s.min_mm).field("max_mm", s.max_mm).field("active_segments", s.active_segments);
  w.end_object();
}

void write_options(JsonWriter& w, const ParameterSet& set) {
  w.field("response_time_ms", scanner::response_time(set).count());
  w.field("restart_mode", restart_mode_name(set.restart_mode));
  w.field("start_pair", set.start_pair);
  w.key("permitted").begin_array();
  for (std::uint8_t from = 1; from <= scanner::kFieldPairCount; ++from) {
    w.begin_array();
    for (const int to : permitted_targets(set, from)) w.value(static_cast<std::int64_t>(to));
    w.end_array();
  }
  w.end_array();
  w.key("warning_output").begin_array();
  for (const auto& name : warning_output_names(set.warning_output)) w.value(name);
  w.end_array();
  w.key("measurement").begin_object();
  w.field("resolution", set.measurement.resolution)
      .field("start", set.measurement.start)
      .field("stop", set.measurement.stop);
  w.end_object();
}

std::string stats_text(const ContourStats& s) {
  char b[96];
  if (s.active_segments == 0) return "none";
  std::snprintf(b, sizeof b, "%5u..%5u mm on %3zu segments", static_cast<unsigned>(s.min_mm),
                static_cast<unsigned>(s.max_mm), s.active_segments);
  return b;
}

}  // namespace

std::string summary_json(const ParameterSet& set) {
  JsonWriter w;
  w.begin_object();
  w.field("format", kSummaryFormat);
  w.field("device_type", scanner::device_type_text(set.identity.device_type));
  w.field("serial_number", scanner::serial_number_text(set.identity.serial_number));
  w.field("firmware", firmware_text(set.identity));
  write_options(w, set);
  w.key("pairs").begin_array();
  for (std::size_t p = 0; p < scanner::kFieldPairCount; ++p) {
    w.begin_object().field("pair", p + 1);
    write_stats(w, "protective", contour_stats(set.pairs[p].protective_mm));
    write_stats(w, "warning", contour_stats(set.pairs[p].warning_mm));
    w.end_object();
  }
  w.end_array().end_object();
  return w.str();
}

std::string summary_text(const ParameterSet& set) {
  std::string out;
  auto line = [&out](std::string_view name, const std::string& value) {
    char b[32];
    std::snprintf(b, sizeof b, "  %-20s ", std::string(name).c_str());
    out += b + value + "\n";
  };
  line("device type", scanner::device_type_text(set.identity.device_type));
  line("serial number", scanner::serial_number_text(set.identity.serial_number));
  line("firmware", firmware_text(set.identity));
  line("response time", std::to_string(scanner::response_time(set).count()) + " ms");
  line("restart mode", restart_mode_name(set.restart_mode));
  line("start pair", std::to_string(set.start_pair));
  for (std::uint8_t from = 1; from <= scanner::kFieldPairCount; ++from) {
    line("from pair " + std::to_string(from) + " to", join(permitted_targets(set, from)));
  }
  line("warning output", join(warning_output_names(set.warning_output)));
  line("measurement", "resolution " + std::to_string(set.measurement.resolution) + ", segments " +
                          std::to_string(set.measurement.start) + ".." +
                          std::to_string(set.measurement.stop));
  for (std::size_t p = 0; p < scanner::kFieldPairCount; ++p) {
    const std::string pair = "pair " + std::to_string(p + 1) + " ";
    line(pair + "protective", stats_text(contour_stats(set.pairs[p].protective_mm)));
    line(pair + "warning", stats_text(contour_stats(set.pairs[p].warning_mm)));
  }
  return out;
}

}  // namespace rs4sim::rs4::report
