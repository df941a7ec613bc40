// PROFIsafe F-device driver ([PROFIsafe V1.30 F-Device behaviour]). See f_device.h and
// docs/profisafe.md.
#include "profisafe/f_device.h"

#include <algorithm>
#include <stdexcept>

namespace rs4sim::profisafe {

FDevice::FDevice(FDeviceConfig config) : config_(config) {
  if (config_.data_size == 0 || config_.data_size > kMaxDataSize) {
    throw std::invalid_argument("FDevice: data_size must be 1..12");
  }
  if (!is_supported_connection(config_.profile.par_version, config_.profile.crc_length)) {
    throw std::invalid_argument(
        "FDevice: V1 needs F_Par_Version 0 with a 2-byte CRC, V2 F_Par_Version 1 with 3 or 4");
  }
  FParameters p;
  p.par_version = config_.profile.par_version;
  p.crc_length = config_.profile.crc_length;
  pdu_config_ = PduConfig::from(p, config_.data_size, config_.crc2_variant);
  build_response();
}

Validation FDevice::set_parameters(std::span<const std::uint8_t> block) {
  validation_ = validate(block, config_.profile);
  fault_bits_ = 0;
  fault_reported_ = false;
  activate_fv_ = false;
  number_ = 0;
  toggle_ = true;
  cons_nr_reset_ = false;
  synced_ = false;
  watchdog_deadline_.reset();
  output_.fill(0);
  if (!validation_.ok()) {
    ++counters_.parameter_errors;
    state_ = FDeviceState::kNoParameters;
  } else {
    const auto params = parse_f_parameters(block).value();
    pdu_config_ = PduConfig::from(params, config_.data_size, config_.crc2_variant);
    wd_time_ms_ = params.wd_time_ms;
    state_ = FDeviceState::kStartup;
  }
  build_response();
  return validation_;
}

void FDevice::set_input(std::span<const std::uint8_t> data) {
  if (data.size() != config_.data_size)
    throw std::invalid_argument("FDevice::set_input: wrong data size");
  std::copy(data.begin(), data.end(), input_.begin());
  build_response();
}

bool FDevice::sends_process_values() const noexcept {
  return state_ == FDeviceState::kRun && !activate_fv_;
}

std::uint8_t FDevice::status_byte() const noexcept {
  if (state_ == FDeviceState::kNoParameters) return 0;
  auto status = static_cast<std::uint8_t>(fault_bits_ |
                                          (sends_process_values() ? 0 : status_bit::kFvActivated));
  if (pdu_config_.version == ProtocolVersion::kV2) {
    if (toggle_) status |= status_bit::kToggleD;
    if (cons_nr_reset_) status |= status_bit::kConsNrR;
  }
  return status;
}

void FDevice::enter_fault(std::uint8_t bit) {
  state_ = FDeviceState::kFault;
  fault_bits_ |= bit;
  fault_reported_ = false;
  output_.fill(0);
}

void FDevice::accept_new(const PduCheck& check, TimePoint now) {
  ++counters_.new_pdus;
  synced_ = true;
  number_ = candidate_;
  toggle_ = candidate_toggle_;
  cons_nr_reset_ = candidate_reset_;
  watchdog_deadline_ = now + std::chrono::milliseconds(wd_time_ms_);
  activate_fv_ = (check.status_or_control & control_bit::kActivateFv) != 0;
  if (state_ == FDeviceState::kFault) {
    // Recovery rule: the first valid new PDU after a fault is answered with the fault
    // status (the host sees it once); the next one returns to kRun.
    if (fault_reported_) {
      state_ = FDeviceState::kRun;
      fault_bits_ = 0;
    } else {
      fault_reported_ = true;
    }
  } else {
    state_ = FDeviceState::kRun;
  }
  if (sends_process_values()) {
    std::copy(check.data.begin(), check.data.end(), output_.begin());
  } else {
    output_.fill(0);
  }
}

FDeviceEvent FDevice::classify_v1(std::span<const std::uint8_t> pdu) {
  last_check_ = check_pdu(pdu_config_, pdu);
  if (!last_check_.ok()) return FDeviceEvent::kCrcError;
  const std::uint8_t n = last_check_.consecutive_number;
  if (synced_ && n == number_) return FDeviceEvent::kRepeat;
  // [PROFIsafe V1.30 F-Device behaviour] UNCERTAIN detail: a wrong number is a communication
  // fault reported as CE_CRC. The device then re-synchronises to the host's next valid number
  // (docs/profisafe.md).
  if (synced_ && n != next_consecutive_number(static_cast<std::uint8_t>(number_)))
    return FDeviceEvent::kNumberError;
  candidate_ = n;
  return FDeviceEvent::kNew;
}

// [IEC 61784-3-3 safety PDU] V2: R_cons_nr restarts the virtual number at 0; otherwise a changed
// Toggle_h makes the PDU new (number + 1) and an unchanged one repeats the current number.
FDeviceEvent FDevice::classify_v2(std::span<const std::uint8_t> pdu) {
  const bool sized = pdu.size() == pdu_size(pdu_config_);
  const std::uint8_t control = sized ? pdu[config_.data_size] : 0;
  const bool reset = (control & control_bit::kRConsNr) != 0;
  const bool toggle = (control & control_bit::kToggleH) != 0;
  const bool same = synced_ && toggle == toggle_;
  const bool is_new = reset ? !(same && number_ == 0) : !same;
  const std::uint32_t expected =
      reset ? 0 : (is_new ? next_virtual_consecutive_number(number_) : number_);
  last_check_ = check_pdu(pdu_config_, pdu, expected);
  if (!last_check_.ok()) {
    return sized && synced_ && !reset && adopt_neighbour(pdu, expected, toggle)
               ? FDeviceEvent::kNumberError
               : FDeviceEvent::kCrcError;
  }
  if (!is_new) return FDeviceEvent::kRepeat;
  candidate_ = expected;
  candidate_toggle_ = toggle;
  candidate_reset_ = reset;
  return FDeviceEvent::kNew;
}

// V2: a PDU whose CRC2 holds with the current number, the one before it or the one after the
// expected one was sent with a repeated or skipped number (DECISION, docs/profisafe.md). The
// device takes that number and toggle, so that its fault answer reaches the host as valid.
bool FDevice::adopt_neighbour(std::span<const std::uint8_t> pdu, std::uint32_t expected,
                              bool toggle) {
  for (const std::uint32_t n :
       {number_, number_ - 1, next_virtual_consecutive_number(expected)}) {
    if (n > 0xFFFFFFu || !check_pdu(pdu_config_, pdu, n).ok()) continue;
    number_ = n;
    toggle_ = toggle;
    return true;
  }
  return false;
}

FDeviceEvent FDevice::on_pdu(std::span<const std::uint8_t> pdu, TimePoint now) {
  on_time(now);  // a PDU arriving at or after the deadline comes too late
  if (state_ == FDeviceState::kNoParameters) return FDeviceEvent::kIgnored;
  ++counters_.pdus;
  const bool v2 = pdu_config_.version == ProtocolVersion::kV2;
  const FDeviceEvent event = v2 ? classify_v2(pdu) : classify_v1(pdu);
  switch (event) {
    case FDeviceEvent::kCrcError:
      ++counters_.crc_errors;
      enter_fault(status_bit::kCeCrc);
      break;
    case FDeviceEvent::kNumberError:
      ++counters_.number_errors;
      enter_fault(status_bit::kCeCrc);
      if (!v2) synced_ = false;  // V2: the host restarts the number with R_cons_nr
      break;
    case FDeviceEvent::kRepeat:
      ++counters_.repeats;
      if (state_ == FDeviceState::kFault) fault_reported_ = true;
      break;
    case FDeviceEvent::kNew: accept_new(last_check_, now); break;
    case FDeviceEvent::kIgnored: break;
  }
  build_response();
  return event;
}

void FDevice::on_time(TimePoint now) {
  if (watchdog_deadline_ && now >= *watchdog_deadline_) {
    // [PROFIsafe V1.30 F-Device behaviour]: no valid new PDU within F_WD_Time → WD_timeout,
    // fail-safe values.
    ++counters_.watchdog_timeouts;
    watchdog_deadline_.reset();
    enter_fault(status_bit::kWdTimeout);
    build_response();
  }
}

std::optional<TimePoint> FDevice::next_deadline() const noexcept { return watchdog_deadline_; }

std::span<const std::uint8_t> FDevice::output() const noexcept {
  return std::span<const std::uint8_t>(output_).first(config_.data_size);
}

void FDevice::build_response() {
  const std::size_t size = pdu_size(pdu_config_);
  response_.fill(0);
  response_size_ = size;
  if (state_ == FDeviceState::kNoParameters) return;  // all-zero PDU (DECISION)
  std::array<std::uint8_t, kMaxDataSize> data{};
  if (sends_process_values()) data = input_;
  const auto written =
      build_pdu(pdu_config_, std::span<const std::uint8_t>(data).first(config_.data_size),
                status_byte(), number_, response_);
  (void)written;
}

// Fault injection (faults.h) on the way out; the true response stays in response_.
void FDevice::apply_faults() {
  wire_ = response_;
  if (faults_.repeat_number > 0 && has_sent_) {
    --faults_.repeat_number;
    wire_ = sent_;
    return;
  }
  const bool skip = faults_.skip_number > 0;
  if (skip) --faults_.skip_number;
  if ((skip || faults_.crc1_override) && state_ != FDeviceState::kNoParameters) {
    PduConfig c = pdu_config_;
    if (faults_.crc1_override) c.crc1 = *faults_.crc1_override;
    const bool v1 = pdu_config_.version == ProtocolVersion::kV1;
    std::uint32_t n = number_;
    if (skip) {
      n = v1 ? next_consecutive_number(static_cast<std::uint8_t>(n))
             : next_virtual_consecutive_number(n);
    }
    const auto written =
        build_pdu(c, std::span<const std::uint8_t>(response_).first(config_.data_size),
                  response_[config_.data_size], n, wire_);
    (void)written;  // cannot fail: the configuration was checked when it was set
  }
  if (faults_.corrupt_crc2 > 0) {
    --faults_.corrupt_crc2;
    wire_[response_size_ - 1] ^= 0x01;
  }
}

std::span<const std::uint8_t> FDevice::response() {
  if (faults_.mute) return {};
  apply_faults();
  sent_ = wire_;
  has_sent_ = true;
  return std::span<const std::uint8_t>(wire_).first(response_size_);
}

}  // namespace rs4sim::profisafe

namespace rs4sim::profisafe {

std::string_view to_token(FDeviceState s) noexcept {
  switch (s) {
    case FDeviceState::kNoParameters: return "no-parameters";
    case FDeviceState::kStartup: return "startup";
    case FDeviceState::kRun: return "run";
    case FDeviceState::kFault: return "fault";
  }
  return "?";
}

// Every token is a string literal, so its data() ends in a NUL.
const char* to_string(FDeviceState s) noexcept { return to_token(s).data(); }

const char* to_string(FDeviceEvent e) noexcept {
  switch (e) {
    case FDeviceEvent::kIgnored: return "ignored";
    case FDeviceEvent::kNew: return "new";
    case FDeviceEvent::kRepeat: return "repeat";
    case FDeviceEvent::kCrcError: return "crc-error";
    case FDeviceEvent::kNumberError: return "number-error";
  }
  return "?";
}

}  // namespace rs4sim::profisafe
