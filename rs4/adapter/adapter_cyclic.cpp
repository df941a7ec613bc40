// Adapter: the cyclic process bytes ([RS4 manual §5.1]) and the Proxy-Enable /
// Proxy-Request / OSSD-release logic of [RS4 manual §7.1, §7.2] ([RS4 manual §5.1, §7.1, §7.2]).
#include "rs4/adapter/adapter.h"

#include <algorithm>

namespace rs4sim::rs4::adapter {

namespace {
bool rs4_operational(scanner::ScannerState s) noexcept {
  return s == scanner::ScannerState::kMeasuring || s == scanner::ScannerState::kError;
}
}  // namespace

// ---- Data_Exchange -------------------------------------------------------------------
void Adapter::on_outputs(std::span<const std::uint8_t> outputs, TimePoint now) {
  if (!powered_) return;
  collect_rs4(now);
  std::fill(output_pdu_.begin(), output_pdu_.end(), std::uint8_t{0});
  std::copy_n(outputs.begin(), std::min(outputs.size(), kPduSize), output_pdu_.begin());
  refresh_input(now);  // the response to this PDU carries the current input byte
  const auto event = fdevice_.on_pdu(outputs, now);
  if (event == profisafe::FDeviceEvent::kCrcError ||
      event == profisafe::FDeviceEvent::kNumberError) {
    // Table 5.3-3 0x2418: the PROFIsafe driver cannot check the cyclic output data.
    adapter_error(protocol::AdapterError::kSafetyDriverCannotCheckOutputs, now);
  }
  if (fdevice_.sends_process_values()) {
    if (event == profisafe::FDeviceEvent::kNew) apply_output_byte(fdevice_.output()[0], now);
  } else {
    // Fail-safe output values: restart low; the selected field pair is kept (a 0 from
    // the safety layer is not a field pair the PLC chose, so no 0x2600).
    output_byte_ = 0;
    restart_bus_ = false;
    drive_restart_input(now);
  }
  ++counters_.cyclic_exchanges;
  errors_.end_cycle();
  refresh_input(now);
}

void Adapter::on_outputs_cleared(dp::slave::OutputClear why, TimePoint now) {
  (void)why;
  if (!powered_) return;
  output_byte_ = 0;
  restart_bus_ = false;
  drive_restart_input(now);
  refresh_input(now);
}

void Adapter::read_inputs(std::span<std::uint8_t> inputs, TimePoint now) {
  std::fill(inputs.begin(), inputs.end(), std::uint8_t{0});
  if (!powered_) return;
  refresh_input(now);
  const auto pdu = fdevice_.response();  // empty while muted by fault injection
  std::fill(input_pdu_.begin(), input_pdu_.end(), std::uint8_t{0});
  std::copy_n(pdu.begin(), std::min(pdu.size(), kPduSize), input_pdu_.begin());
  std::copy_n(pdu.begin(), std::min(pdu.size(), inputs.size()), inputs.begin());
}

// [RS4 manual §5.1.2]: restart bit → RS4 restart input; Proxy-Enable only at DP start-up and after
// the PC adapter was removed; field pair 1..4 → RS4.
void Adapter::apply_output_byte(std::uint8_t out, TimePoint now) {
  output_byte_ = out;
  const auto bits = decode_output_byte(out);
  if (bits.reserved != 0 && config_.check_reserved_output_bits) {
    // Table 5.3-3 0x2419 "processing the output data gives no consistent result": bits 5..3 must
    // be 0 [RS4 manual §5.1.2]. The byte is not applied (restart low, field pair kept), reported
    // once while it persists [docs/decisions.md#rs4-inconsistent-outputs].
    restart_bus_ = false;
    drive_restart_input(now);
    if (inconsistent_output_ != out) {
      inconsistent_output_ = out;
      adapter_error(protocol::AdapterError::kOutputsInconsistent, now);
    }
    return;
  }
  inconsistent_output_.reset();
  // Proxy-Enable 0: the OSSD bit is released without the proxy ([RS4 manual §5.1.2, §7.1, §7.2]).
  gate_.process_output(bits.proxy_enable, proxy_.running());
  restart_bus_ = bits.restart;
  drive_restart_input(now);
  apply_field_pair(bits.field_pair, now);
}

// [RS4 manual §5.1.2]: an invalid number is not forwarded, gives 0x2600 and OSSD bit 0; the bit is
// released ≈500 ms after a valid number is present again.
void Adapter::apply_field_pair(std::uint8_t pair, TimePoint now) {
  if (pair >= 1 && pair <= 4) {
    if (field_pair_error_) {
      field_pair_error_ = false;
      field_pair_release_at_ = now + config_.field_pair_release;
    }
    if (pair != field_pair_) {
      field_pair_ = pair;
      scanner_.select_field_pair(pair, now);
    }
    return;
  }
  if (field_pair_error_) {
    last_error_at_ = now;  // the error persists: no going alarm yet
    return;
  }
  field_pair_error_ = true;
  field_pair_release_at_.reset();
  ++counters_.field_pair_errors;
  adapter_error(protocol::AdapterError::kWrongFieldPair, now);
}

void Adapter::drive_restart_input(TimePoint now) {
  const bool want = restart_bus_ || restart_button_;
  if (want == restart_driven_) return;
  restart_driven_ = want;
  scanner_.set_restart_input(want, now);
}

void Adapter::set_restart_button(bool pressed, TimePoint now) {
  restart_button_ = pressed;
  if (!powered_) return;
  drive_restart_input(now);
  refresh_input(now);
}

// ---- [RS4 manual §7.1, §7.2]: RS4 start-up, PC adapter, proxy -----------------------------------
void Adapter::update_rs4_phase(TimePoint now) {
  (void)now;
  if (gate_.rs4_up() || !rs4_operational(scanner_.status().state)) return;
  // [RS4 manual §7.1.1]: the RS4 is operational (≈30 s after power-on); with a PC adapter at
  // start-up no Proxy-Request, the OSSD follows the RS4.
  if (gate_.rs4_operational(pc_.attached())) request_sync(protocol::SyncReason::kPowerUp);
}

void Adapter::attach_pc_adapter(TimePoint now) {
  // [RS4 manual §5.1.1] bit 3: during a sync the RS232 is switched through only after the sync
  // ends.
  pc_.attach(proxy_.running());
  // [RS4 manual §7.1.2]: no Proxy-Request while attached; a pending one is withdrawn (a running
  // sync has reset it already) and the removal sets it again.
  gate_.withdraw_request();
  if (powered_) refresh_input(now);
}

void Adapter::detach_pc_adapter(TimePoint now) {
  const bool was = pc_.attached();
  pc_.detach();
  if (!powered_ || !was) return;
  // [RS4 manual §5.1.1] bit 3: on 1→0 the Proxy-Request bit is always set; Proxy-Enable is read
  // again.
  if (gate_.rs4_up() && !proxy_.running()) request_sync(protocol::SyncReason::kPcAdapterRemoved);
  gate_.forget_proxy_enable();
  refresh_input(now);
}

// ---- the input byte ----------------------------------------------------------------------
Adapter::Rs4Signals Adapter::sample_rs4() const noexcept {
  const auto st = scanner_.status();
  return {scanner_.ossd(), st.warning_output, st.protective_violated, st.warning_violated};
}

// [RS4 manual, technical data] "Reaktionszeit PROFIsafe-Adapter 10 ms": what the RS4 shows now
// reaches the input byte `response_time` later; every change travels on its own.
void Adapter::follow_rs4_signals(TimePoint now) {
  const auto s = sample_rs4();
  const auto& last = signal_line_.empty() ? seen_ : signal_line_.back().second;
  if (s != last) {
    if (config_.response_time <= milliseconds::zero()) {
      signal_line_.clear();
      seen_ = s;
    } else {
      signal_line_.emplace_back(now + config_.response_time, s);
    }
  }
  while (!signal_line_.empty() && signal_line_.front().first <= now) {
    seen_ = signal_line_.front().second;
    signal_line_.pop_front();
  }
}

void Adapter::refresh_input(TimePoint now) {
  track_led(now);
  if (powered_) follow_rs4_signals(now);
  input_byte_ = powered_ ? compose_input_byte(now) : 0;
  fdevice_.set_input(std::span<const std::uint8_t>(&input_byte_, 1));
}

// THE predicate of the OSSD bit ([docs/design.md#one-predicate-for-the-safe-state];
// [RS4 manual §5.1.1, §5.1.2, §7.1, §7.2]). The bit may read
// 1 only when every one of these holds; every other path leaves it 0:
//  - the safety layer exchanges process values (FDevice kRun, no activate_FV),
//  - the RS4 is operational and the parameter check of [RS4 manual §7.1, §7.2] passed or is not
//  needed,
//  - no error of bit 5 ([RS4 manual §5.1.1] bit 5 "(OSSD = 0 im Fehlerfall)"): an RS4 fault,
//    a wrong field pair, inconsistent outputs or a one-shot adapter error until its going
//    alarm [docs/decisions.md#rs4-error-bit],
//  - ≥500 ms passed since a valid field pair number returned,
//  - both OSSDs of the RS4 are on, as the adapter sees them (`response_time` after the RS4).
bool Adapter::ossd_release_allowed(TimePoint now) const noexcept {
  if (!powered_ || !connected_ || !fdevice_.sends_process_values()) return false;
  if (!gate_.open()) return false;
  if (error_present()) return false;
  if (field_pair_release_at_ && now < *field_pair_release_at_) return false;
  return seen_.ossd;  // both OSSDs of the RS4 on, as the adapter sees them
}

// [RS4 manual §5.1.1] bit 5 "Es ist ein Fehler im RS4 oder im PROFIsafe-Adapter aufgetreten".
bool Adapter::error_present() const noexcept {
  const auto st = scanner_.status();
  return st.fault || st.state == scanner::ScannerState::kError || field_pair_error_ ||
         inconsistent_output_.has_value() || adapter_error_active_;
}

// The only function that composes the input byte; bit 7 comes from the predicate above.
std::uint8_t Adapter::compose_input_byte(TimePoint now) const noexcept {
  const auto st = scanner_.status();
  InputBits bits;
  bits.ossd = ossd_release_allowed(now);
  bits.warning_output_active = seen_.warning_output;
  bits.error = error_present();
  bits.not_operational = !gate_.open() || !rs4_operational(st.state);
  bits.rs232_active = pc_.switched_through();
  bits.proxy_request = gate_.proxy_request();
  bits.protective_field = seen_.protective;
  bits.warning_field = seen_.warning;
  return encode_input_byte(bits);
}

}  // namespace rs4sim::rs4::adapter
