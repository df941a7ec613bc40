// Adapter: RS4 events, PROFI_CMD_GET_RS4_DATA forwarding, error memory and diagnosis
// alarms ([RS4 manual §5.2.2, §5.3, §5.2.2.2, §5.3.2]).
#include "rs4/adapter/adapter.h"
#include "rs4/adapter/rs4_commands.h"
#include "rs4/protocol/adapter_command.h"

#include <algorithm>

namespace rs4sim::rs4::adapter {

// Runs the scanner up to `now` and takes its 0x53/0x54 events: each one is an error of
// the RS4 (error memory, diagnosis alarm) and, when forwarding asks for it, goes to the
// second buffer ([RS4 manual §5.2.2]: "a slow master gets both measurements and errors").
void Adapter::collect_rs4(TimePoint now) {
  scanner_.advance(now);
  update_rs4_phase(now);
  while (auto e = scanner_.pop_event()) {
    if (event_listener_) event_listener_(*e);
    const bool error = e->kind == scanner::Rs4Event::Kind::kError;
    const auto bit = error ? protocol::kForwardError : protocol::kForwardWarning;
    if ((forwarding_.mask & bit) != 0) {
      if (event_buffer_.size() < config_.event_buffer) {
        event_buffer_.push_back(event_telegram(scanner_, *e));
      }
    }
    // DECISION: the RS4's number goes into the μC2 fields ([RS4 manual §5.3.2] "μC2 error number
    // (or of the RS4)") and the μC2 ring; μC1 reports 0 for it.
    report_error(e->number, 0, e->at);
  }
  // An error that is still present keeps the alarm "coming" ([RS4 manual §5.3.2] "Liegt
  // mindestens 500 ms kein Fehler mehr vor, so wird ein gehender Alarm gesendet"). A warning
  // (a contaminated window) is no error, as for input bit 5: it has its coming alarm, but does
  // not hold the going one back [docs/decisions.md#rs4-going-alarm-and-warnings].
  const auto st = scanner_.status();
  if (st.fault || field_pair_error_ || inconsistent_output_) {
    last_error_at_ = now;
  }
  capture_forwarding();
  refresh_input(now);  // the RS4 state may have changed: the input byte follows at once
}

// First buffer: the next measurement (or alive) telegram, only after the previous one
// was fetched ([RS4 manual §5.2.2]).
void Adapter::capture_forwarding() {
  const auto want = forwarding_.mask & (protocol::kForwardMeasurement | protocol::kForwardAlive);
  if (want == 0 || forwarding_.telegram) return;
  const auto st = scanner_.status();
  const bool scanning = (st.state == scanner::ScannerState::kMeasuring ||
                         st.state == scanner::ScannerState::kError) &&
                        st.scan_counter != 0;
  if (!scanning) return;
  const auto scan = scanner_.last_scan().scan_number;
  if (forwarding_.last_scan && *forwarding_.last_scan == scan) return;
  forwarding_.last_scan = scan;
  forwarding_.telegram = (want & protocol::kForwardMeasurement) != 0
                             ? measurement_telegram(scanner_)
                             : alive_telegram(scanner_);
}

std::optional<std::vector<std::uint8_t>> Adapter::take_forwarded() {
  std::optional<std::vector<std::uint8_t>> t;
  if (!event_buffer_.empty()) {
    t = std::move(event_buffer_.front());
    event_buffer_.pop_front();
  } else if (forwarding_.telegram) {
    t = std::move(forwarding_.telegram);
    forwarding_.telegram.reset();
  }
  if (t && !forwarding_.permanent) {  // mode 0: forward one telegram
    forwarding_.mask = 0;
    forwarding_.telegram.reset();
    event_buffer_.clear();
  }
  if (t) capture_forwarding();
  return t;
}

// DECISION: an adapter error (table 5.3-3) is seen by both processors; it is entered in
// both rings and reported in both fields of the diagnosis alarm.
// Input bit 5 ([RS4 manual §5.1.1] "an error in the RS4 or in the adapter"): an error with a
// state (a wrong field pair, inconsistent outputs) sets it while present; a one-shot error
// (an acyclic telegram, a PROFIsafe PDU, a proxy step) until its going alarm; the OSSD bit is 0
// while bit 5 is 1 ("OSSD = 0 im Fehlerfall") [docs/decisions.md#rs4-error-bit].
void Adapter::adapter_error(protocol::AdapterError e, TimePoint now) {
  const auto wire = protocol::to_wire(e);
  if (e != protocol::AdapterError::kWrongFieldPair &&
      e != protocol::AdapterError::kOutputsInconsistent) {
    adapter_error_active_ = true;
  }
  report_error(wire, wire, now);
}

void Adapter::report_error(std::uint16_t uc2_error, std::uint16_t uc1_error, TimePoint now) {
  if (uc2_error != 0) errors_.record(Processor::kUc2, uc2_error);
  if (uc1_error != 0) errors_.record(Processor::kUc1, uc1_error);
  last_uc2_error_ = uc2_error;
  last_uc1_error_ = uc1_error;
  error_active_ = true;
  last_error_at_ = now;
  const auto key = uc2_error != 0 ? uc2_error : uc1_error;
  if (!connected_) return;  // reported at the next data exchange ([RS4 manual §5.3.2])
  if (std::find(reported_.begin(), reported_.end(), key) != reported_.end()) return;
  reported_.push_back(key);  // [RS4 manual §5.3.2]: once per error while the link stays up
  submit_diagnosis_alarm(protocol::AlarmDifferentiation::kAppears);
}

// [RS4 manual §5.3.2]: 0D 01 00 spec | 84 e2 e2 c2 c2 e1 e1 c1 c1; the slave adds the 4-byte header
// (length, type, slot, specifier with its own sequence number).
void Adapter::submit_diagnosis_alarm(protocol::AlarmDifferentiation d) {
  if (!control_) return;
  protocol::DiagnosisAlarm a;
  a.differentiation = d;
  a.uc2_error = last_uc2_error_;
  a.uc2_count = errors_.count(Processor::kUc2, last_uc2_error_);
  a.uc1_error = last_uc1_error_;
  a.uc1_count = errors_.count(Processor::kUc1, last_uc1_error_);
  const auto pdu = protocol::encode_diagnosis_alarm(a);
  dp::slave::AlarmRequest req;
  req.type = protocol::kAlarmTypeDiagnosis;
  req.slot = 0;
  req.specifier = static_cast<std::uint8_t>(d);
  req.add_ack = true;  // specifier bit 2 = 1: acknowledge required
  req.user_data = std::span<const std::uint8_t>(pdu).subspan(4);
  if (control_->submit_alarm(req)) {
    ++counters_.alarms_refused;
  } else {
    ++counters_.alarms_submitted;
  }
}

// [RS4 manual §5.3.2]: after ≥500 ms without an error, a going alarm.
void Adapter::check_going_alarm(TimePoint now) {
  if (!error_active_ || now - last_error_at_ < config_.going_alarm_delay) return;
  error_active_ = false;
  adapter_error_active_ = false;
  refresh_input(now);
  reported_.clear();
  if (connected_) submit_diagnosis_alarm(protocol::AlarmDifferentiation::kDisappears);
}

}  // namespace rs4sim::rs4::adapter
