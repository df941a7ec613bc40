// PROFIsafe F-host driver, V1 and V2 ([PROFIsafe V1.30 F-Device behaviour] [IEC 61784-3-3 safety
// PDU]). See f_host.h and
// docs/profisafe.md.
#include "profisafe/f_host.h"

#include <algorithm>
#include <stdexcept>

namespace rs4sim::profisafe {

FHost::FHost(FHostConfig config) : config_(config) {
  if (!is_supported_connection(config_.params.par_version, config_.params.crc_length)) {
    throw std::invalid_argument(
        "FHost: V1 needs F_Par_Version 0 with a 2-byte CRC, V2 F_Par_Version 1 with 3 or 4");
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
  if (pdu_config_.version == ProtocolVersion::kV2) {
    // DECISION (docs/profisafe.md): V2 leaves the PDU in flight and restarts the number.
    restart_ = true;
    outstanding_ = false;
  }
}

void FHost::ack_rei() noexcept {
  if (state_ != FHostState::kAckRequired) return;
  state_ = FHostState::kRun;
  ++counters_.reintegrations;
}

// V1: n + 1 (1..255); V2: the virtual number + 1, or 0 on a restart; a skip fault adds one.
void FHost::advance_number() {
  previous_number_ = number_;
  const bool v1 = pdu_config_.version == ProtocolVersion::kV1;
  auto next = [v1](std::uint32_t n) {
    return v1 ? next_consecutive_number(static_cast<std::uint8_t>(n))
              : next_virtual_consecutive_number(n);
  };
  number_ = (!v1 && restart_) ? 0 : next(number_);
  if (faults_.skip_number > 0) {
    --faults_.skip_number;
    number_ = next(number_);
  }
  toggle_h_ = !toggle_h_;
}

void FHost::build_new_pdu(TimePoint now) {
  if (started_) previous_pdu_ = pdu_;
  has_previous_ = started_;
  started_ = true;
  const bool reset = restart_ && pdu_config_.version == ProtocolVersion::kV2;
  advance_number();
  restart_ = false;
  // While passivated the host sends fail-safe output values with activate_FV (DECISION).
  const bool fail_safe = state_ != FHostState::kRun;
  std::array<std::uint8_t, kMaxDataSize> data{};
  if (!fail_safe) data = output_;
  auto control =
      static_cast<std::uint8_t>(fail_safe || user_activate_fv_ ? control_bit::kActivateFv : 0);
  if (pdu_config_.version == ProtocolVersion::kV2) {
    if (toggle_h_) control |= control_bit::kToggleH;
    if (reset) control |= control_bit::kRConsNr;
  }
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
    const std::uint32_t n =
        pdu_config_.version == ProtocolVersion::kV1 ? fields[ds + 1] : number_;
    const auto written =
        build_pdu(c, std::span<const std::uint8_t>(fields).first(ds), fields[ds], n, wire_);
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

FHostEvent FHost::classify_v1() {
  const std::uint8_t n = last_check_.consecutive_number;
  if (outstanding_ && n == previous_consecutive_number(static_cast<std::uint8_t>(number_))) {
    return FHostEvent::kStale;  // the device has not seen number_ yet; the watchdog keeps running
  }
  return (!outstanding_ || n != number_) ? FHostEvent::kNumberError : FHostEvent::kValid;
}

// V2: valid = CRC2 over number_ and Toggle_d = Toggle_h; an answer over the previous number
// with the previous toggle is stale.
FHostEvent FHost::classify_v2(std::span<const std::uint8_t> pdu) {
  const bool sized = pdu.size() == pdu_size(pdu_config_);
  const bool toggle_d = sized && (pdu[config_.data_size] & status_bit::kToggleD) != 0;
  if (last_check_.ok()) {
    if (!outstanding_) return FHostEvent::kNumberError;
    return toggle_d == toggle_h_ ? FHostEvent::kValid : FHostEvent::kStale;
  }
  if (has_previous_ && toggle_d != toggle_h_) {
    const PduCheck previous = check_pdu(pdu_config_, pdu, previous_number_);
    if (previous.ok()) {
      last_check_ = previous;
      return FHostEvent::kStale;
    }
  }
  return FHostEvent::kCrcError;
}

FHostEvent FHost::on_pdu(std::span<const std::uint8_t> pdu, TimePoint now) {
  on_time(now);
  if (!started_) return FHostEvent::kNotExpected;
  ++counters_.answers;
  const bool v2 = pdu_config_.version == ProtocolVersion::kV2;
  last_check_ = check_pdu(pdu_config_, pdu, number_);
  FHostEvent event = FHostEvent::kCrcError;
  if (v2) {
    event = classify_v2(pdu);
  } else if (last_check_.ok()) {
    event = classify_v1();
  }
  if (event == FHostEvent::kStale) {
    ++counters_.stale;
    return event;
  }
  if (event != FHostEvent::kValid) {
    ++(event == FHostEvent::kCrcError ? counters_.crc_errors : counters_.number_errors);
    passivate();
    return event;
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
