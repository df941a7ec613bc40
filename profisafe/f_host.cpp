// PROFIsafe F-host driver, V1 ([PROFIsafe V1.30 F-Device behaviour]). See f_host.h and
// docs/profisafe.md.
#include "profisafe/f_host.h"

#include <algorithm>
#include <stdexcept>

namespace rs4sim::profisafe {

FHost::FHost(FHostConfig config) : config_(config) {
  if (config_.params.par_version != 0 || config_.params.crc_length != CrcLength::k2Byte) {
    throw std::invalid_argument("FHost: only PROFIsafe V1 (F_Par_Version 0, 2-byte CRC) is driven");
  }
  if (config_.data_size == 0 || config_.data_size > kMaxDataSize) {
    throw std::invalid_argument("FHost: data_size must be 1..12");
  }
  config_.params.par_crc = profisafe::crc1(config_.params);
  pdu_config_ = PduConfig::from(config_.params, config_.data_size, config_.crc2_variant);
}

std::array<std::uint8_t, kFParametersSize> FHost::parameter_block() const noexcept {
  FParameters p = config_.params;
  if (parameter_faults_.dest_add) p.dest_add = *parameter_faults_.dest_add;
  if (parameter_faults_.source_add) p.source_add = *parameter_faults_.source_add;
  // A wrong address alone gives a block with a matching CRC1 (the device reports the
  // address); a wrong F_Par_CRC is injected on top.
  p.par_crc = parameter_faults_.par_crc.value_or(profisafe::crc1(p));
  return encode_f_parameters_raw(p);
}

void FHost::set_output(std::span<const std::uint8_t> data) {
  if (data.size() != config_.data_size)
    throw std::invalid_argument("FHost::set_output: wrong data size");
  std::copy(data.begin(), data.end(), output_.begin());
}

void FHost::passivate() {
  if (state_ == FHostState::kRun || state_ == FHostState::kAckRequired) ++counters_.passivations;
  if (state_ != FHostState::kStartup) state_ = FHostState::kPassivated;
  input_.fill(0);
}

void FHost::ack_rei() noexcept {
  if (state_ != FHostState::kAckRequired) return;
  state_ = FHostState::kRun;
  ++counters_.reintegrations;
}

void FHost::build_new_pdu(TimePoint now) {
  if (has_previous_ || number_ != 0) previous_pdu_ = pdu_;
  has_previous_ = number_ != 0;
  number_ = next_consecutive_number(number_);
  if (faults_.skip_number > 0) {
    --faults_.skip_number;
    number_ = next_consecutive_number(number_);
  }
  // While passivated the host sends fail-safe output values with activate_FV (DECISION).
  const bool fail_safe = state_ != FHostState::kRun;
  std::array<std::uint8_t, kMaxDataSize> data{};
  if (!fail_safe) data = output_;
  const auto control =
      static_cast<std::uint8_t>(fail_safe || user_activate_fv_ ? control_bit::kActivateFv : 0);
  const auto written =
      build_pdu(pdu_config_, std::span<const std::uint8_t>(data).first(config_.data_size), control,
                number_, pdu_);
  (void)written;  // cannot fail: the configuration was checked in the constructor
  outstanding_ = true;
  watchdog_deadline_ = now + std::chrono::milliseconds(config_.params.wd_time_ms);
}

std::span<const std::uint8_t> FHost::request(TimePoint now) {
  on_time(now);
  if (!outstanding_) build_new_pdu(now);
  if (faults_.mute) return {};
  ++counters_.requests;
  wire_ = pdu_;
  if (faults_.repeat_number > 0 && has_previous_) {
    --faults_.repeat_number;
    wire_ = previous_pdu_;
  }
  const std::size_t size = pdu_size(pdu_config_);
  if (faults_.crc1_override) {  // applied on the way out, so that removing it heals at once
    PduConfig c = pdu_config_;
    c.crc1 = *faults_.crc1_override;
    const std::size_t ds = config_.data_size;
    const auto fields = wire_;  // build_pdu must not read and write the same buffer
    const auto written = build_pdu(c, std::span<const std::uint8_t>(fields).first(ds), fields[ds],
                                   fields[ds + 1], wire_);
    (void)written;
  }
  if (faults_.corrupt_crc2 > 0) {
    --faults_.corrupt_crc2;
    wire_[size - 1] ^= 0x01;
  }
  return std::span<const std::uint8_t>(wire_).first(size);
}

void FHost::handle_valid(const PduCheck& check) {
  last_status_ = check.status_or_control;
  outstanding_ = false;  // the answer to number_ arrived: advance with the next request
  watchdog_deadline_.reset();
  const bool ce_crc = (last_status_ & status_bit::kCeCrc) != 0;
  const bool wd = (last_status_ & status_bit::kWdTimeout) != 0;
  if (ce_crc) ++counters_.device_ce_crc;
  if (wd) ++counters_.device_wd_timeout;
  if (ce_crc || wd) {
    passivate();
    return;
  }
  if (state_ == FHostState::kStartup) state_ = FHostState::kRun;
  if (state_ == FHostState::kPassivated) state_ = FHostState::kAckRequired;
  if (state_ == FHostState::kRun) {
    std::copy(check.data.begin(), check.data.end(), input_.begin());
  } else {
    input_.fill(0);
  }
}

FHostEvent FHost::on_pdu(std::span<const std::uint8_t> pdu, TimePoint now) {
  on_time(now);
  if (number_ == 0) return FHostEvent::kNotExpected;
  ++counters_.answers;
  last_check_ = check_pdu(pdu_config_, pdu);
  if (!last_check_.ok()) {
    ++counters_.crc_errors;
    passivate();
    return FHostEvent::kCrcError;
  }
  const std::uint8_t n = last_check_.consecutive_number;
  if (outstanding_ && n == previous_consecutive_number(number_)) {
    ++counters_.stale;  // the device has not seen number_ yet; the watchdog keeps running
    return FHostEvent::kStale;
  }
  if (!outstanding_ || n != number_) {
    ++counters_.number_errors;
    passivate();
    return FHostEvent::kNumberError;
  }
  handle_valid(last_check_);
  return (last_status_ & (status_bit::kCeCrc | status_bit::kWdTimeout)) != 0
             ? FHostEvent::kDeviceFault
             : FHostEvent::kValid;
}

void FHost::on_time(TimePoint now) {
  if (watchdog_deadline_ && now >= *watchdog_deadline_) {
    // [PROFIsafe V1.30 F-Device behaviour]: no valid answer within F_WD_Time → passivate; keep
    // waiting for the answer.
    ++counters_.watchdog_timeouts;
    watchdog_deadline_.reset();
    passivate();
  }
}

std::optional<TimePoint> FHost::next_deadline() const noexcept { return watchdog_deadline_; }

std::span<const std::uint8_t> FHost::input() const noexcept {
  static const std::array<std::uint8_t, kMaxDataSize> kZero{};
  if (state_ != FHostState::kRun)
    return std::span<const std::uint8_t>(kZero).first(config_.data_size);
  return std::span<const std::uint8_t>(input_).first(config_.data_size);
}

std::string_view to_token(FHostState s) noexcept {
  switch (s) {
    case FHostState::kStartup: return "startup";
    case FHostState::kRun: return "run";
    case FHostState::kPassivated: return "passivated";
    case FHostState::kAckRequired: return "ack-required";
  }
  return "?";
}

// Every token is a string literal, so its data() ends in a NUL.
const char* to_string(FHostState s) noexcept { return to_token(s).data(); }

const char* to_string(FHostEvent e) noexcept {
  switch (e) {
    case FHostEvent::kValid: return "valid";
    case FHostEvent::kStale: return "stale";
    case FHostEvent::kCrcError: return "crc-error";
    case FHostEvent::kNumberError: return "number-error";
    case FHostEvent::kDeviceFault: return "device-fault";
    case FHostEvent::kNotExpected: return "not-expected";
  }
  return "?";
}

}  // namespace rs4sim::profisafe
