#include "rs4/report/parameter_diff.h"

#include "rs4/report/json_writer.h"
#include "rs4/scanner/identity_text.h"

#include <cstdlib>

namespace rs4sim::rs4::report {
namespace {

using scanner::ParameterSet;

void compare(std::vector<ValueChange>& out, std::string field, const std::string& old_value,
             const std::string& new_value) {
  if (old_value != new_value) out.push_back({std::move(field), old_value, new_value});
}

std::vector<ValueChange> identity_changes(const ParameterSet& a, const ParameterSet& b) {
  std::vector<ValueChange> out;
  compare(out, "serial_number", scanner::serial_number_text(a.identity.serial_number),
          scanner::serial_number_text(b.identity.serial_number));
  compare(out, "device_type", scanner::device_type_text(a.identity.device_type),
          scanner::device_type_text(b.identity.device_type));
  compare(out, "firmware", firmware_text(a.identity), firmware_text(b.identity));
  return out;
}

std::vector<ValueChange> option_changes(const ParameterSet& a, const ParameterSet& b) {
  std::vector<ValueChange> out;
  compare(out, "response_time_ms", std::to_string(scanner::response_time(a).count()),
          std::to_string(scanner::response_time(b).count()));
  compare(out, "restart_mode", restart_mode_name(a.restart_mode),
          restart_mode_name(b.restart_mode));
  compare(out, "start_pair", std::to_string(a.start_pair), std::to_string(b.start_pair));
  for (std::uint8_t from = 1; from <= scanner::kFieldPairCount; ++from) {
    compare(out, "permitted.from_pair_" + std::to_string(from), join(permitted_targets(a, from)),
            join(permitted_targets(b, from)));
  }
  compare(out, "warning_output", join(warning_output_names(a.warning_output)),
          join(warning_output_names(b.warning_output)));
  compare(out, "measurement.resolution", std::to_string(a.measurement.resolution),
          std::to_string(b.measurement.resolution));
  compare(out, "measurement.start", std::to_string(a.measurement.start),
          std::to_string(b.measurement.start));
  compare(out, "measurement.stop", std::to_string(a.measurement.stop),
          std::to_string(b.measurement.stop));
  return out;
}

std::vector<SegmentRange> changed_ranges(const scanner::Contour& a, const scanner::Contour& b) {
  std::vector<SegmentRange> ranges;
  bool open = false;
  for (std::size_t n = 0; n < scanner::kSegmentCount; ++n) {
    const int change = int{b[n]} - int{a[n]};
    if (change == 0) {
      open = false;
      continue;
    }
    if (!open) ranges.push_back({n, n, change});
    open = true;
    auto& r = ranges.back();
    r.last = n;
    if (std::abs(change) > std::abs(r.max_change_mm)) r.max_change_mm = change;
  }
  return ranges;
}

std::string signed_mm(int mm) { return (mm > 0 ? "+" : "") + std::to_string(mm) + " mm"; }

std::string range_text(const SegmentRange& r) {
  if (r.first == r.last) {
    return "segment " + std::to_string(r.first) + " changed, " + signed_mm(r.max_change_mm);
  }
  return "segments " + std::to_string(r.first) + "-" + std::to_string(r.last) + " changed, max " +
         signed_mm(r.max_change_mm);
}

void write_changes(JsonWriter& w, std::string_view name, const std::vector<ValueChange>& changes) {
  w.key(name).begin_array();
  for (const auto& c : changes) {
    w.begin_object().field("field", c.field).field("old", c.old_value).field("new", c.new_value);
    w.end_object();
  }
  w.end_array();
}

}  // namespace

ParameterDiff diff(const ParameterSet& old_set, const ParameterSet& new_set) {
  ParameterDiff d;
  d.identity = identity_changes(old_set, new_set);
  d.options = option_changes(old_set, new_set);
  for (std::size_t i = 0; i < scanner::kUserPasswordCount; ++i) {
    if (old_set.passwords[i] != new_set.passwords[i])
      d.passwords_changed.push_back(static_cast<int>(i) + 1);
  }
  for (std::size_t p = 0; p < scanner::kFieldPairCount; ++p) {
    for (const auto kind : {ContourKind::kProtective, ContourKind::kWarning}) {
      auto ranges =
          changed_ranges(contour_of(old_set.pairs[p], kind), contour_of(new_set.pairs[p], kind));
      if (!ranges.empty()) d.contours.push_back({static_cast<int>(p + 1), kind, std::move(ranges)});
    }
  }
  return d;
}

std::string render_text(const ParameterDiff& d) {
  if (d.empty()) return "no differences\n";
  std::string out;
  for (const auto& c : d.identity) {
    out += "identity " + c.field + ": " + c.old_value + " -> " + c.new_value + "\n";
  }
  for (const auto& c : d.options) out += c.field + ": " + c.old_value + " -> " + c.new_value + "\n";
  for (const int n : d.passwords_changed) {
    out += "user password " + std::to_string(n) + " changed\n";
  }
  for (const auto& c : d.contours) {
    const std::string head =
        "pair " + std::to_string(c.pair) + " " + std::string(contour_name(c.contour)) + ": ";
    for (const auto& r : c.ranges) out += head + range_text(r) + "\n";
  }
  return out;
}

std::string render_json(const ParameterDiff& d) {
  JsonWriter w;
  w.begin_object().field("identical", d.empty());
  write_changes(w, "identity", d.identity);
  write_changes(w, "options", d.options);
  w.key("passwords_changed").begin_array();
  for (const int n : d.passwords_changed) w.value(static_cast<std::int64_t>(n));
  w.end_array();
  w.key("contours").begin_array();
  for (const auto& c : d.contours) {
    w.begin_object().field("pair", c.pair).field("contour", contour_name(c.contour));
    w.key("ranges").begin_array();
    for (const auto& r : c.ranges) {
      w.begin_object().field("first", r.first).field("last", r.last);
      w.field("max_change_mm", r.max_change_mm).end_object();
    }
    w.end_array().end_object();
  }
  w.end_array().end_object();
  return w.str();
}

}  // namespace rs4sim::rs4::report
