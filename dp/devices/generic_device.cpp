#include "dp/devices/generic_device.h"

#include <algorithm>

namespace rs4sim::dp::devices {

namespace {
using pdu::ErrorCode1;
constexpr std::uint8_t kProcessAlarm = 2;  // [IEC 61158-6-3 DPV1 alarms] Alarm_Type

dp::slave::AcyclicResult dpv1_error(ErrorCode1 code1, std::uint8_t code2 = 0) {
  return dp::slave::AcyclicResult::fail({0x80, code1, code2});
}

std::uint16_t record_key(std::uint8_t slot, std::uint8_t index) {
  return static_cast<std::uint16_t>(slot << 8 | index);
}
}  // namespace

GenericDevice::GenericDevice(GenericDeviceConfig config) : cfg_(std::move(config.cfg)) {
  if (cfg_.empty()) {  // Chk_Cfg carries 1…244 identifier bytes ([IEC 61158-6-3 Set_Prm])
    throw std::system_error(make_error_code(pdu::PduError::kTooShort),
                            "generic device: at least one configuration identifier is needed");
  }
  auto summary = pdu::summarize_cfg(cfg_, pdu::CfgService::kGetCfg);
  if (!summary) throw std::system_error(summary.error(), "generic device configuration");
  if (summary.value().input_bytes > 244 || summary.value().output_bytes > 244) {
    throw std::system_error(make_error_code(pdu::PduError::kTooLong),
                            "generic device: I/O image longer than 244 bytes "
                            "([IEC 61158-6-3 Chk_Cfg/Get_Cfg])");
  }
  input_length_ = summary.value().input_bytes;
  output_length_ = summary.value().output_bytes;
  outputs_.resize(output_length_, 0);
}

dp::slave::PrmVerdict GenericDevice::check_parameters(const pdu::SetPrm& prm, TimePoint now) {
  (void)now;
  user_prm_.assign(prm.user_data.begin(), prm.user_data.end());
  return dp::slave::PrmVerdict::kAccept;
}

dp::slave::CfgVerdict GenericDevice::check_config(std::span<const std::uint8_t> cfg,
                                                  bool user_check, TimePoint now) {
  (void)now;
  if (std::ranges::equal(cfg, cfg_)) return dp::slave::CfgVerdict::kAccept;
  if (user_check) {  // DPV1 Check_Cfg_Mode: same image lengths are enough
                     // ([IEC 61158-6-3 DPV1_Status])
    auto summary = pdu::summarize_cfg(cfg, pdu::CfgService::kChkCfg);
    if (summary && summary.value().input_bytes == input_length_ &&
        summary.value().output_bytes == output_length_) {
      return dp::slave::CfgVerdict::kAccept;
    }
  }
  return dp::slave::CfgVerdict::kCfgFault;
}

void GenericDevice::on_outputs(std::span<const std::uint8_t> outputs, TimePoint) {
  ++exchanges_;
  const std::size_t n = std::min(outputs.size(), outputs_.size());
  std::copy_n(outputs.begin(), n, outputs_.begin());
}

void GenericDevice::on_outputs_cleared(dp::slave::OutputClear, TimePoint) {
  std::fill(outputs_.begin(), outputs_.end(), std::uint8_t{0});
}

void GenericDevice::read_inputs(std::span<std::uint8_t> inputs, TimePoint now) {
  (void)now;
  const std::size_t n = std::min(inputs.size(), outputs_.size());
  std::copy_n(outputs_.begin(), n, inputs.begin());
  std::fill(inputs.begin() + static_cast<std::ptrdiff_t>(n), inputs.end(), std::uint8_t{0});
}

void GenericDevice::on_state_change(dp::slave::State, dp::slave::State to,
                                    dp::slave::TransitionReason, TimePoint) {
  state_ = to;
}

dp::slave::AcyclicResult GenericDevice::on_acyclic(const dp::slave::AcyclicRequest& req,
                                                   TimePoint) {
  switch (req.service) {
    case dp::slave::AcyclicService::kRead: return read_record(req);
    case dp::slave::AcyclicService::kWrite: return write_record(req);
    case dp::slave::AcyclicService::kDataTransport: break;
  }
  return dpv1_error(ErrorCode1::kFeatureNotSupported);
}

dp::slave::AcyclicResult GenericDevice::read_record(const dp::slave::AcyclicRequest& req) const {
  const auto it = records_.find(record_key(req.slot, req.index));
  if (it == records_.end()) return dpv1_error(ErrorCode1::kInvalidIndex);
  const std::size_t n = std::min<std::size_t>(req.length, it->second.size());
  return dp::slave::AcyclicResult::ok(std::span<const std::uint8_t>(it->second).first(n));
}

dp::slave::AcyclicResult GenericDevice::write_record(const dp::slave::AcyclicRequest& req) {
  if (req.slot == 0 && req.index == kAlarmTriggerIndex) {
    if (req.data.size() > dp::slave::kMaxAlarmUserData)
      return dpv1_error(ErrorCode1::kWriteLengthError);
    const std::error_code ec = raise_alarm(kProcessAlarm, 0, req.data);
    if (ec) return dpv1_error(ErrorCode1::kStateConflict, static_cast<std::uint8_t>(ec.value()));
    return dp::slave::AcyclicResult::ok();
  }
  const std::uint16_t key = record_key(req.slot, req.index);
  auto it = records_.find(key);
  if (it == records_.end()) {
    if (records_.size() >= kMaxRecords) return dpv1_error(ErrorCode1::kResourceUnavailable);
    it = records_.emplace(key, std::vector<std::uint8_t>{}).first;
  }
  it->second.assign(req.data.begin(), req.data.end());
  return dp::slave::AcyclicResult::ok();
}

std::error_code GenericDevice::raise_alarm(std::uint8_t type, std::uint8_t slot,
                                           std::span<const std::uint8_t> user_data) {
  if (control_ == nullptr) return std::make_error_code(std::errc::not_connected);
  dp::slave::AlarmRequest a;
  a.type = type;
  a.slot = slot;
  a.specifier = 1;  // appears ([IEC 61158-6-3 DPV1 alarms])
  a.user_data = user_data;
  return control_->submit_alarm(a);
}

void GenericDevice::on_alarm_acknowledged(const dp::slave::AlarmAck& ack, TimePoint) {
  acked_.push_back(ack);
}

const std::vector<std::uint8_t>* GenericDevice::record(std::uint8_t slot,
                                                       std::uint8_t index) const {
  const auto it = records_.find(record_key(slot, index));
  return it == records_.end() ? nullptr : &it->second;
}

}  // namespace rs4sim::dp::devices
