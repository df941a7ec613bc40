// A GSD station's F-module as a PROFIsafe F-device. See f_device_module.h.
#include "gsd/f_device_module.h"

#include "gsd/syntax.h"

#include <algorithm>

namespace rs4sim::gsd {
namespace {

std::uint16_t clamp16(std::int64_t v) {
  return static_cast<std::uint16_t>(std::clamp<std::int64_t>(v, 0, 0xFFFF));
}

// The device's own values: the GSD's defaults fixed, F_WD_Time and F_Source_Add in the GSD's
// ranges, F_Dest_Add its address switch.
profisafe::DeviceProfile device_profile(const FModuleInfo& info, std::uint16_t dest_add) {
  profisafe::DeviceProfile profile = profisafe::profile_for(info.parameters);
  profile.dest_add = dest_add;
  for (const auto& f : info.fields) {
    if (syntax::iequals(f.param->name, "F_WD_Time")) {
      profile.min_wd_time_ms = clamp16(std::max<std::int64_t>(f.param->min, 1));
      profile.max_wd_time_ms = clamp16(f.param->max);
    } else if (syntax::iequals(f.param->name, "F_Source_Add")) {
      profile.min_source_add = clamp16(f.param->min);
      profile.max_source_add = clamp16(f.param->max);
    }
  }
  return profile;
}

}  // namespace

FModuleDevice::FModuleDevice(profisafe::FDeviceConfig config, const Placement& placement)
    : config_(config),
      device_(config),
      module_(placement.module),
      slot_(placement.slot),
      data_size_(config.data_size),
      prm_offset_(placement.prm_offset),
      input_offset_(placement.input_offset),
      output_offset_(placement.output_offset),
      pdu_size_(placement.pdu_size) {}

Result<FModuleDevice> FModuleDevice::make(const Device& device, const SlaveSetup& setup,
                                          const FParameterBlock& block, std::size_t input_offset,
                                          std::size_t output_offset, std::uint16_t dest_add) {
  const Module& m = device.modules[setup.slots[block.module].index];
  RS4SIM_GSD_TRY(const FModuleInfo info, describe_f_module(device, m));
  const std::size_t size = info.io.f_input_bytes;
  if (size != info.io.f_output_bytes || size == 0 || size > profisafe::kMaxDataSize) {
    return Error{GsdError::kFParameterLayout, device.file, m.line, "",
                 "module \"" + m.name + "\": " + std::to_string(info.io.f_input_bytes) +
                     " F-input and " + std::to_string(info.io.f_output_bytes) +
                     " F-output bytes: the F-device serves 1..12 bytes, the same both ways"};
  }
  const Placement placement{block.module,  setup.slots[block.module].slot,
                            block.offset,  input_offset,
                            output_offset, size + info.io.overhead()};
  return FModuleDevice(profisafe::FDeviceConfig{device_profile(info, dest_add), size, {}},
                       placement);
}

profisafe::Validation FModuleDevice::set_parameters(std::span<const std::uint8_t> user_prm_data) {
  wd_time_ms_ = 0;
  if (user_prm_data.size() < prm_offset_ + profisafe::kFParametersSize) {
    return device_.set_parameters({});  // no block: not a layout the device knows (70)
  }
  const auto block = user_prm_data.subspan(prm_offset_, profisafe::kFParametersSize);
  const auto v = device_.set_parameters(block);
  if (v.ok()) wd_time_ms_ = profisafe::parse_f_parameters(block).value().wd_time_ms;
  return v;
}

std::array<std::uint8_t, 5> FModuleDevice::status_block() const noexcept {
  return {0x05, 0x81, static_cast<std::uint8_t>(slot_), 0x00, diagnosis()};
}

void FModuleDevice::on_outputs(std::span<const std::uint8_t> outputs, profisafe::TimePoint now) {
  const bool fits = outputs.size() >= output_offset_ + pdu_size_;
  last_event_ = device_.on_pdu(fits ? outputs.subspan(output_offset_, pdu_size_)
                                    : std::span<const std::uint8_t>{},
                               now);
  if (last_event_ == profisafe::FDeviceEvent::kNew ||
      last_event_ == profisafe::FDeviceEvent::kRepeat) {
    host_control_ = device_.last_check().status_or_control;
  }
}

void FModuleDevice::write_inputs(std::span<std::uint8_t> inputs, profisafe::TimePoint now) {
  if (hold_.count() > 0 && !held_until_) held_until_ = now + hold_;
  if (held_until_ && now >= *held_until_) {
    held_until_.reset();
    hold_ = std::chrono::milliseconds(0);
  }
  if (!held_until_) {
    const auto pdu = device_.response();  // empty while muted: the last one stays
    std::copy(pdu.begin(), pdu.end(), sent_.begin());
  }
  if (inputs.size() < input_offset_ + pdu_size_) return;
  std::copy_n(sent_.begin(), pdu_size_,
              inputs.begin() + static_cast<std::ptrdiff_t>(input_offset_));
}

void FModuleDevice::set_f_inputs(std::span<const std::uint8_t> data) {
  device_.set_input(data);
  std::copy(data.begin(), data.end(), f_inputs_.begin());
}

void FModuleDevice::restart(std::uint16_t dest_add) {
  config_.profile.dest_add = dest_add;
  device_ = profisafe::FDevice(config_);
  device_.set_input(f_inputs());
  sent_.fill(0);
  hold_ = std::chrono::milliseconds(0);
  held_until_.reset();
  wd_time_ms_ = 0;
  host_control_ = 0;
  last_event_ = profisafe::FDeviceEvent::kIgnored;
}

std::string_view f_state_token(const profisafe::FDevice& device) noexcept {
  switch (device.state()) {
    case profisafe::FDeviceState::kNoParameters:
      return device.diagnosis() != 0 ? "parameter-fault" : "waiting-for-parameters";
    case profisafe::FDeviceState::kStartup: return "startup";
    case profisafe::FDeviceState::kRun:
      return device.sends_process_values() ? "run" : "fail-safe-values";
    case profisafe::FDeviceState::kFault: return "passivated";
  }
  return "?";
}

std::string_view f_mode_token(const profisafe::FDevice& device) noexcept {
  return device.version() == profisafe::ProtocolVersion::kV2 ? "V2" : "V1";
}

}  // namespace rs4sim::gsd
