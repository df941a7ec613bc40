// Inputs of the scanner model: restart button/bit, field pair selection, faults,
// window contamination, configuration (docs/rs4-scanner.md).
#include "rs4/scanner/parameter_codec.h"
#include "rs4/scanner/scanner.h"

#include <algorithm>

namespace rs4sim::rs4::scanner {

// ----- restart ([RS4 manual §4.3, §5.1.2] bit 7) ---------------------------------------------

// While the input is high the OSSDs are off. On release the pulse counts only if it
// lasted 0.12 s … 5 s (both included); shorter or longer pulses are ignored.
void Scanner::set_restart_input(bool high, TimePoint now) {
  advance(now);
  steady_ = false;
  if (high == restart_held_) return;
  restart_held_ = high;
  if (high) {
    restart_pressed_at_ = now;
  } else {
    const auto held = now - restart_pressed_at_;
    if (held < kRestartPulseMin) {
      ++counters_.restart_too_short;
    } else if (held > kRestartPulseMax) {
      ++counters_.restart_too_long;
    } else {
      ++counters_.restart_accepted;
      on_restart_pulse(now);
    }
  }
  apply_ossd();
}

// An accepted pulse acknowledges a fault whose cause is gone (a new start follows), or
// releases the interlock when the protective field is free.
void Scanner::on_restart_pulse(TimePoint at) {
  if (state_ == ScannerState::kError && !any_fault_present()) {
    for (FaultState& f : faults_) f.latched = false;
    start_measuring(at);
    return;
  }
  if (state_ == ScannerState::kMeasuring && interlock_ && scanned_since_start_ &&
      violated_scans_ == 0) {
    interlock_ = false;
    return;
  }
  ++counters_.restart_without_effect;
}

// ----- field pairs ([RS4 manual §5.1.2] bits 0..2, option 3) -------------------------------------

void Scanner::select_field_pair(std::uint8_t pair, TimePoint now) {
  advance(now);
  steady_ = false;
  requested_pair_ = pair;
  if (state_ == ScannerState::kMeasuring) request_pair(pair, now);
  apply_ossd();
}

// A number outside 1..4 or a transition the parameter set does not permit is a device
// fault (kFieldPairInvalid / kFieldPairSequence); a permitted switch makes the new pair
// active and keeps the old one selected (and monitored) for the next scan.
void Scanner::request_pair(std::uint8_t pair, TimePoint at) {
  if (pair == active_pair_) return;
  if (pair < 1 || pair > kFieldPairCount) {
    raise_fault(Fault::kFieldPairInvalid, pair, at);
  } else if (!permits(params_, active_pair_, pair)) {
    raise_fault(Fault::kFieldPairSequence, static_cast<std::uint16_t>(active_pair_ << 8U | pair),
                at);
  } else {
    second_pair_ = active_pair_;
    active_pair_ = pair;
    ++counters_.field_pair_switches;
  }
}

// ----- faults ------------------------------------------------------------------------

boost::outcome_v2::std_result<void> Scanner::inject_fault(Fault fault, TimePoint now) {
  if (static_cast<std::size_t>(fault) >= kFaultCount) return ScannerError::kUnknownFault;
  advance(now);
  steady_ = false;
  raise_fault(fault, 0, now);
  apply_ossd();
  return boost::outcome_v2::success();
}

void Scanner::unknown_command(std::uint8_t code, TimePoint now) {
  advance(now);
  steady_ = false;
  raise_fault(Fault::kUnknownCommand, code, now);
  apply_ossd();
}

boost::outcome_v2::std_result<void> Scanner::clear_fault(Fault fault, TimePoint now) {
  if (static_cast<std::size_t>(fault) >= kFaultCount) return ScannerError::kUnknownFault;
  advance(now);
  steady_ = false;
  faults_[static_cast<std::size_t>(fault)].present = false;
  return boost::outcome_v2::success();
}

// A fault is present while its cause lasts; it stays latched (OSSD off, error state)
// until a restart pulse acknowledges it after the cause is gone. One error event (0x53)
// per occurrence. Field-pair faults are events, not lasting causes.
void Scanner::raise_fault(Fault fault, std::uint16_t parameter, TimePoint at) {
  FaultState& f = faults_[static_cast<std::size_t>(fault)];
  const bool lasting = fault != Fault::kFieldPairInvalid && fault != Fault::kFieldPairSequence &&
                       fault != Fault::kUnknownCommand;
  f.present = lasting;
  if (f.latched) return;
  f.latched = true;
  ++f.occurrences;
  ++counters_.faults;
  if (state_ == ScannerState::kMeasuring) state_ = ScannerState::kError;
  if (state_ != ScannerState::kOff) {
    const FaultInfo& info = fault_info(fault);
    push_event(Rs4Event{Rs4Event::Kind::kError, info.error_number, parameter, info.function, at});
  }
}

bool Scanner::any_fault_present() const noexcept {
  return std::any_of(faults_.begin(), faults_.end(), [](const FaultState& f) { return f.present; });
}

bool Scanner::any_fault_latched() const noexcept {
  return std::any_of(faults_.begin(), faults_.end(), [](const FaultState& f) { return f.latched; });
}

// ----- window contamination ([RS4 manual §5.1.1] bit 6, [RS4 manual §5.2.3.3]) -------------------

void Scanner::set_contamination(std::uint8_t percent, TimePoint now) {
  advance(now);
  steady_ = false;
  contamination_percent_ = std::min<std::uint8_t>(percent, 100);
  if (scanning()) update_contamination(now);
  apply_ossd();
}

void Scanner::update_contamination(TimePoint at) {
  const bool warning = contamination_percent_ >= config_.contamination_warning_percent;
  if (warning && !contamination_warning_) {
    push_event(Rs4Event{Rs4Event::Kind::kWarning, kWarningContaminationNumber,
                        contamination_percent_, kWarningContaminationFunction, at});
  }
  contamination_warning_ = warning;
  auto& fault = faults_[static_cast<std::size_t>(Fault::kWindowContaminated)];
  if (contamination_percent_ >= config_.contamination_fault_percent) {
    raise_fault(Fault::kWindowContaminated, contamination_percent_, at);
  } else {
    fault.present = false;
  }
}

// ----- configuration ([RS4 manual §7.1.2]: OSSD off while the RS4's set changes) -----------------

boost::outcome_v2::std_result<void> Scanner::enter_configuration(TimePoint now) {
  advance(now);
  if (!scanning()) return ScannerError::kNotMeasuring;
  steady_ = false;
  state_ = ScannerState::kConfiguration;
  apply_ossd();
  return boost::outcome_v2::success();
}

boost::outcome_v2::std_result<void> Scanner::set_parameters(const ParameterSet& set,
                                                            TimePoint now) {
  advance(now);
  if (state_ != ScannerState::kConfiguration && state_ != ScannerState::kOff) {
    return ScannerError::kNotInConfiguration;
  }
  if (validate(set)) return ScannerError::kInvalidParameterSet;
  params_ = set;
  params_.identity = config_.identity;  // the serial number belongs to the device
  ++change_counter_;                    // wraps like a 16-bit device counter
  return boost::outcome_v2::success();
}

boost::outcome_v2::std_result<void> Scanner::leave_configuration(TimePoint now) {
  advance(now);
  if (state_ != ScannerState::kConfiguration) return ScannerError::kNotInConfiguration;
  start_measuring(now);
  return boost::outcome_v2::success();
}

void Scanner::reset_to_factory_default(TimePoint now) {
  advance(now);
  steady_ = false;
  ParameterSet fresh = merge_download(params_, factory_default());
  const bool running = scanning() || state_ == ScannerState::kConfiguration;
  params_ = fresh;
  ++change_counter_;
  if (running) start_measuring(now);
  apply_ossd();
}

bool Scanner::factory_settings() const {
  return params_ == merge_download(params_, factory_default());
}

std::uint32_t Scanner::parameter_checksum() const { return checksum(params_); }
std::uint32_t Scanner::transfer_checksum() const { return scanner::transfer_checksum(params_); }

Scene& Scanner::edit_scene(TimePoint now) {
  advance(now);
  steady_ = false;
  return scene_;
}

}  // namespace rs4sim::rs4::scanner
