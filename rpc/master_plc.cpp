#include "rpc/master_plc.h"

#include "rs4/adapter/cyclic_bytes.h"

#include <algorithm>
#include <iterator>

namespace rs4sim::rpc {

namespace adapter = rs4::adapter;

std::optional<std::uint8_t> MasterPlc::output_byte(std::uint8_t address) const {
  if (station_ == nullptr) return std::nullopt;
  const auto v = station_->view(address);
  if (!v) return std::nullopt;
  return v->output_byte;
}

bool MasterPlc::manual_acknowledge(std::uint8_t address) const {
  return output_byte(address).has_value() && !station_->auto_ack_rei();
}

// The F-host's acknowledgement is one setting of the master side for all its RS4s.
void MasterPlc::set_manual_acknowledge(std::uint8_t address, bool manual) {
  if (output_byte(address)) station_->set_auto_ack_rei(!manual);
}

bool MasterPlc::in_start_interlock(const rs4::device::Rs4SlaveView& v) {
  const auto in = adapter::decode_input_byte(v.input_byte);
  return v.data_exchange() && v.safety == profisafe::FHostState::kRun && !in.ossd &&
         !in.not_operational && !in.error && !in.protective_field;
}

void MasterPlc::pulse(std::uint8_t address, dp::Duration length) {
  const auto byte = output_byte(address).value_or(0);
  if ((byte & adapter::kOutputRestart) != 0) return;  // held by the API: not ours to pulse
  set_output_byte(address, static_cast<std::uint8_t>(byte | adapter::kOutputRestart));
  after(length, [this, address] {
    const auto now = output_byte(address).value_or(0);
    set_output_byte(address, static_cast<std::uint8_t>(now & ~adapter::kOutputRestart));
  });
}

void MasterPlc::on_cycle(dp::TimePoint now) {
  now_ = now;
  std::vector<Due> ready;
  const auto split = std::stable_partition(due_.begin(), due_.end(),
                                           [now](const Due& d) { return d.at > now; });
  std::move(split, due_.end(), std::back_inserter(ready));
  due_.erase(split, due_.end());
  for (auto& d : ready) d.f();
  if (!restart_pulse_ || station_ == nullptr) return;
  for (const auto address : station_->slave_addresses()) {
    const auto v = station_->view(address);
    if (!v || !v->data_exchange()) {
      pulsed_.erase(address);  // the next start-up gets its pulse
    } else if (!pulsed_.contains(address) && in_start_interlock(*v)) {
      pulsed_.insert(address);
      pulse(address, *restart_pulse_);
    }
  }
}

}  // namespace rs4sim::rpc
