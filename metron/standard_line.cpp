#include "metron/standard_line.h"

#include <algorithm>

namespace rs4sim::metron {

StandardLine::StandardLine(const Options& options)
    : o_(options),
      format_{options.format, options.separator, options.checksum},
      line_(line_settings(options)) {}

void StandardLine::start(stream::TimePoint now) {
  next_cycle_ = now + o_.scan_cycle;
  if (o_.reporting_mode == ReportingMode::kPeriodical) next_period_ = now + o_.period;
}

void StandardLine::on_bytes(std::span<const std::uint8_t> bytes) {
  for (const auto b : bytes) {
    if (b == o_.wire.request_char && o_.reporting_mode == ReportingMode::kOnRequest) {
      ++stats_.requests;
      request_pending_ = true;
    } else {
      ++stats_.other_bytes;
    }
  }
}

void StandardLine::on_input(bool high, const Scene& scene) {
  const bool start_stop =
      o_.input_type == InputType::kStartStopLine || o_.input_type == InputType::kStartStopAll;
  if (o_.reporting_mode != ReportingMode::kInputRelated || !start_stop) return;
  if (high && !tracking_) {  // leading edge: monitoring starts
    tracking_ = true;
    repeats_left_ = 0;
    maximum_ = scene.measure(o_.report.front());
  } else if (!high && tracking_) {  // trailing edge: the maximum goes out three times
    tracking_ = false;
    repeats_left_ = 3;
  }
}

void StandardLine::on_scene(const Scene& scene) {
  if (tracking_) maximum_ = std::max(maximum_, scene.measure(o_.report.front()));
}

void StandardLine::advance(stream::TimePoint now, const Scene& scene, std::vector<Outgoing>& out) {
  // Cycles and periods in time order, so that "busy" sees the earlier report.
  while (true) {
    const bool cycle_due = next_cycle_ && *next_cycle_ <= now;
    const bool period_due = next_period_ && *next_period_ <= now;
    if (!cycle_due && !period_due) return;
    if (period_due && (!cycle_due || *next_period_ <= *next_cycle_)) {
      send_scene(*next_period_, scene, out);
      *next_period_ += o_.period;
    } else {
      cycle(*next_cycle_, scene, out);
      *next_cycle_ += o_.scan_cycle;
    }
  }
}

void StandardLine::cycle(stream::TimePoint t, const Scene& scene, std::vector<Outgoing>& out) {
  on_scene(scene);
  switch (o_.reporting_mode) {
    case ReportingMode::kContinuous: send_scene(t, scene, out); return;
    case ReportingMode::kPeriodical: return;
    case ReportingMode::kOnRequest:
      if (request_pending_ && !busy(t)) request_pending_ = !send_scene(t, scene, out);
      return;
    case ReportingMode::kStatusChange: {
      if (busy(t)) return;
      auto beams = scene.packed(true);
      if (last_beams_ && *last_beams_ == beams) return;
      last_beams_ = std::move(beams);
      send_scene(t, scene, out);
      return;
    }
    case ReportingMode::kInputRelated: input_related(t, scene, out); return;
  }
}

void StandardLine::input_related(stream::TimePoint t, const Scene& scene,
                                 std::vector<Outgoing>& out) {
  switch (o_.input_type) {
    case InputType::kNoFunction: send_scene(t, scene, out); return;
    case InputType::kEnableLine:
    case InputType::kEnableAll:
      if (scene.input_high()) send_scene(t, scene, out);
      return;
    case InputType::kStartStopLine:
    case InputType::kStartStopAll:
      if (repeats_left_ > 0 && !busy(t)) {
        const std::uint8_t value[1] = {maximum_};
        if (send(t, encode_report(value, format_, o_.wire, o_.checksum_reading), out))
          --repeats_left_;
      }
      return;
    case InputType::kLineStandby:
    case InputType::kAllStandby:
      if (scene.input_high() && !last_sent_.empty())
        send(t, last_sent_, out);  // the last message, not composed again
      else
        send_scene(t, scene, out);
      return;
  }
}

std::vector<std::uint8_t> StandardLine::compose(const Scene& scene) const {
  std::vector<std::uint8_t> values;
  values.reserve(o_.report.size());
  for (const auto m : o_.report) values.push_back(scene.measure(m));
  return encode_report(values, format_, o_.wire, o_.checksum_reading);
}

bool StandardLine::send_scene(stream::TimePoint t, const Scene& scene, std::vector<Outgoing>& out) {
  return send(t, compose(scene), out);
}

bool StandardLine::send(stream::TimePoint t, std::vector<std::uint8_t> bytes,
                        std::vector<Outgoing>& out) {
  if (busy(t)) {
    ++stats_.dropped;
    return false;
  }
  busy_until_ = t + send_time(bytes.size(), line_);
  last_sent_ = bytes;
  out.push_back({t, std::move(bytes)});
  ++stats_.reports;
  return true;
}

std::optional<stream::TimePoint> StandardLine::deadline() const {
  if (!next_cycle_) return std::nullopt;
  if (next_period_) return std::min(*next_cycle_, *next_period_);
  return next_cycle_;
}

}  // namespace rs4sim::metron
