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
  if (config_.profile.par_version != 0 || config_.profile.crc_length != CrcLength::k2Byte) {
    throw std::invalid_argument(
        "FDevice: only PROFIsafe V1 (F_Par_Version 0, 2-byte CRC) is driven");
  }
  pdu_config_.data_size = config_.data_size;
  pdu_config_.variant = config_.crc2_variant;
  build_response();
}

Validation FDevice::set_parameters(std::span<const std::uint8_t> block) {
  validation_ = validate(block, config_.profile);
  fault_bits_ = 0;
  fault_reported_ = false;
  activate_fv_ = false;
  last_number_ = 0;
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
  return static_cast<std::uint8_t>(fault_bits_ |
                                   (sends_process_values() ? 0 : status_bit::kFvActivated));
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
  last_number_ = check.consecutive_number;
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

FDeviceEvent FDevice::on_pdu(std::span<const std::uint8_t> pdu, TimePoint now) {
  on_time(now);  // a PDU arriving at or after the deadline comes too late
  if (state_ == FDeviceState::kNoParameters) return FDeviceEvent::kIgnored;
  ++counters_.pdus;
  last_check_ = check_pdu(pdu_config_, pdu);
  FDeviceEvent event = FDeviceEvent::kNew;
  if (!last_check_.ok()) {
    ++counters_.crc_errors;
    enter_fault(status_bit::kCeCrc);
    event = FDeviceEvent::kCrcError;
  } else if (synced_ && last_check_.consecutive_number == last_number_) {
    ++counters_.repeats;
    if (state_ == FDeviceState::kFault) fault_reported_ = true;
    event = FDeviceEvent::kRepeat;
  } else if (synced_ && last_check_.consecutive_number != next_consecutive_number(last_number_)) {
    // [PROFIsafe V1.30 F-Device behaviour] UNCERTAIN detail: a wrong number is a communication
    // fault reported as CE_CRC. The device then re-synchronises to the host's next valid number
    // (docs/profisafe.md).
    ++counters_.number_errors;
    enter_fault(status_bit::kCeCrc);
    synced_ = false;
    event = FDeviceEvent::kNumberError;
  } else {
    accept_new(last_check_, now);
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
                status_byte(), last_number_, response_);
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
  const std::size_t number_at = config_.data_size + 1;
  const bool skip = faults_.skip_number > 0;
  if (skip) --faults_.skip_number;
  if ((skip || faults_.crc1_override) && state_ != FDeviceState::kNoParameters) {
    PduConfig c = pdu_config_;
    if (faults_.crc1_override) c.crc1 = *faults_.crc1_override;
    const std::uint8_t n =
        skip ? next_consecutive_number(response_[number_at]) : response_[number_at];
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
