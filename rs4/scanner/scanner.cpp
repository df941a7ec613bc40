#include "rs4/scanner/scanner.h"

#include <algorithm>

namespace rs4sim::rs4::scanner {

const char* to_string(ScannerState s) noexcept {
  switch (s) {
    case ScannerState::kOff: return "off";
    case ScannerState::kInitialisation: return "initialisation";
    case ScannerState::kMeasuring: return "measuring";
    case ScannerState::kConfiguration: return "configuration";
    case ScannerState::kError: return "error";
  }
  return "unknown";
}

Scanner::Scanner(ScannerConfig config) : config_(config), params_(factory_default()) {
  params_.identity = config_.identity;
  last_.contour.fill(kNoEchoMm);
}

// ----- the safety rule ---------------------------------------------------------------

// THE predicate: the only reason the OSSDs may be on. Everything not listed keeps them
// off: powered off, booting, configuration, error state, any unacknowledged fault, the
// restart button held ([RS4 manual §4.3]), the interlock waiting for a pulse, no scan yet. The
// OSSDs switch on only after a free scan and, once on, switch off after T/40 ms
// consecutive violated scans (the response time, docs/rs4-scanner.md "OSSD model").
bool Scanner::ossd_may_be_on() const noexcept {
  if (state_ != ScannerState::kMeasuring) return false;
  if (any_fault_latched()) return false;
  if (restart_held_ || interlock_ || !scanned_since_start_) return false;
  const bool field_free = violated_scans_ == 0;
  const bool within_response_time = ossd_ && violated_scans_ < scans_to_switch_off(params_);
  return field_free || within_response_time;
}

// The only function that writes the OSSD state.
void Scanner::apply_ossd() noexcept {
  const bool on = ossd_may_be_on();
  if (ossd_ && !on) ++counters_.ossd_off_switches;
  ossd_ = on;
}

// ----- lifecycle -------------------------------------------------------------------

void Scanner::power_on(TimePoint now) {
  if (state_ != ScannerState::kOff) return;
  state_ = ScannerState::kInitialisation;
  boot_end_ = now + config_.boot_duration;
  scan_counter_ = 0;
  ++counters_.boots;
  if (restart_held_) restart_pressed_at_ = now;
  apply_ossd();
}

void Scanner::power_off(TimePoint now) {
  advance(now);
  state_ = ScannerState::kOff;
  steady_ = false;
  interlock_ = false;
  violated_scans_ = 0;
  scanned_since_start_ = false;
  active_pair_ = 0;
  second_pair_ = 0;
  contamination_warning_ = false;
  for (FaultState& f : faults_) f.latched = false;  // causes (present) survive
  event_count_ = 0;
  last_ = ScanResult{};
  last_.contour.fill(kNoEchoMm);
  apply_ossd();
}

void Scanner::power_cycle(TimePoint now) {
  power_off(now);
  power_on(now);
}

void Scanner::advance(TimePoint now) {
  if (state_ == ScannerState::kInitialisation && now >= boot_end_) start_measuring(boot_end_);
  run_scans(now);
}

TimePoint Scanner::next_deadline() const noexcept {
  if (state_ == ScannerState::kInitialisation) return boot_end_;
  if (scanning()) return next_scan_;
  return TimePoint::max();
}

bool Scanner::scanning() const noexcept {
  return state_ == ScannerState::kMeasuring || state_ == ScannerState::kError;
}

// Entry into protective operation: after boot, after a fault acknowledge, after
// configuration. A start: the start interlock applies ([RS4 manual §5.1.2] Info: "Anlauf nach einem
// Fehler oder nach dem Einschalten"), the start pair is active first and the pair at the
// input is then reached like any other switch (so it must be permitted from the start pair).
void Scanner::start_measuring(TimePoint at) {
  state_ = ScannerState::kMeasuring;
  steady_ = false;
  interlock_ = params_.restart_mode != RestartMode::kAutomatic;
  violated_scans_ = 0;
  scanned_since_start_ = false;
  active_pair_ = params_.start_pair;
  second_pair_ = 0;
  next_scan_ = at;
  update_contamination(at);
  if (any_fault_latched()) {
    state_ = ScannerState::kError;
  } else if (requested_pair_ != active_pair_) {
    request_pair(requested_pair_, at);
    second_pair_ = 0;  // nothing to overlap before the first scan
  }
  apply_ossd();
  run_scans(at);  // the first scan is due at once
}

// ----- scans -------------------------------------------------------------------------

void Scanner::run_scans(TimePoint now) {
  while (scanning() && next_scan_ <= now) {
    if (steady_) {  // identical scans: only the counter moves
      const auto n = static_cast<std::uint64_t>((now - next_scan_) / config_.scan_period) + 1;
      scan_counter_ += static_cast<std::uint32_t>(n);  // wraps like the device's counter
      counters_.scans += n;
      next_scan_ += config_.scan_period * static_cast<std::int64_t>(n);
      last_.scan_number = scan_counter_;
      last_.at = next_scan_ - config_.scan_period;
      return;
    }
    do_scan(next_scan_);
    next_scan_ += config_.scan_period;
  }
}

void Scanner::do_scan(TimePoint at) {
  const bool cached = rendered_revision_ == scene_.revision();
  if (!cached) {
    scene_.render(last_.contour);
    rendered_revision_ = scene_.revision();
  }
  const bool same_pair =
      last_.first_pair == active_pair_ && last_.second_pair == 0 && second_pair_ == 0;
  last_.first = evaluate(last_.contour, params_.pairs[active_pair_ - 1U]);
  last_.first_pair = active_pair_;
  last_.second_pair = second_pair_;
  last_.second =
      second_pair_ != 0 ? evaluate(last_.contour, params_.pairs[second_pair_ - 1U]) : FieldFlags{};
  second_pair_ = 0;  // the switch-over ends with this scan

  const bool violated = last_.first.protective_violated() || last_.second.protective_violated();
  const std::uint32_t k = scans_to_switch_off(params_);
  const std::uint32_t before = violated_scans_;
  violated_scans_ = violated ? std::min(violated_scans_ + 1, k) : 0;
  if (violated_scans_ >= k && state_ == ScannerState::kMeasuring &&
      params_.restart_mode == RestartMode::kStartRestartInterlock) {
    interlock_ = true;  // [RS4 manual §4.3]: restart only after a pulse
  }
  const bool first_scan = !scanned_since_start_;
  scanned_since_start_ = true;
  ++scan_counter_;
  ++counters_.scans;
  last_.scan_number = scan_counter_;
  last_.at = at;

  const bool ossd_before = ossd_;
  apply_ossd();
  const bool saturated = violated_scans_ == 0 || violated_scans_ == k;
  steady_ = cached && same_pair && !first_scan && before == violated_scans_ && saturated &&
            ossd_before == ossd_;
}

// ----- observation -------------------------------------------------------------------

bool Scanner::warning_output() const noexcept {
  if (!scanning()) return false;
  const std::uint8_t w = params_.warning_output;
  return ((w & kWarnOnContamination) != 0 && contamination_warning_) ||
         ((w & kWarnOnWarningField) != 0 && last_.first.warning_violated()) ||
         ((w & kWarnOnFault) != 0 && state_ == ScannerState::kError) ||
         ((w & kWarnOnRestartInterlock) != 0 && interlock_);
}

ScannerStatus Scanner::status() const noexcept {
  ScannerStatus s;
  s.state = state_;
  s.ossd = ossd_;
  s.warning_output = warning_output();
  const bool scanned = scanning() && scanned_since_start_;
  s.protective_violated = scanned && last_.first.protective_violated();
  s.warning_violated = scanned && last_.first.warning_violated();
  s.second_protective_violated = scanned && last_.second.protective_violated();
  s.second_warning_violated = scanned && last_.second.warning_violated();
  // A switch-over shows two selected pairs from the switch until the scan after the one
  // that monitored both (option 3, [RS4 manual §5.2.3]: "zwei Schutzfeldpaare gleichzeitig
  // ausgewählt").
  s.contamination_warning = contamination_warning_;
  s.fault = state_ == ScannerState::kError || any_fault_latched();
  s.restart_interlock = interlock_ && state_ == ScannerState::kMeasuring;
  s.first_pair = scanning() ? active_pair_ : 0;
  s.second_pair = scanning() ? (second_pair_ != 0 ? second_pair_ : last_.second_pair) : 0;
  s.restart_held = restart_held_;
  s.contamination_percent = contamination_percent_;
  s.scan_counter = scan_counter_;
  return s;
}

ScannerLeds Scanner::leds() const noexcept {
  if (state_ == ScannerState::kOff) return {};
  // LED5 from the contamination warning threshold on (the fault threshold lies above it).
  return {restart_held_, contamination_warning_};
}

std::optional<Rs4Event> Scanner::pop_event() noexcept {
  if (event_count_ == 0) return std::nullopt;
  const Rs4Event e = events_[event_head_];
  event_head_ = (event_head_ + 1) % kEventCapacity;
  --event_count_;
  return e;
}

void Scanner::push_event(const Rs4Event& e) noexcept {
  if (event_count_ == kEventCapacity) {  // drop the oldest, keep the newest
    event_head_ = (event_head_ + 1) % kEventCapacity;
    --event_count_;
    ++counters_.events_dropped;
  }
  events_[(event_head_ + event_count_) % kEventCapacity] = e;
  ++event_count_;
}

}  // namespace rs4sim::rs4::scanner
