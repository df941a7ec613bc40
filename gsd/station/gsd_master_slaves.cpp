#include "gsd/station/gsd_master_slaves.h"

#include <algorithm>

namespace rs4sim::gsd {

std::span<const std::uint8_t> ext_diagnosis(const dp::fdl::DataUnit& slave_diag) {
  constexpr std::size_t kStandardDiagBytes = 6;  // [IEC 61158-6-3 Slave_Diag]
  if (slave_diag.size() <= kStandardDiagBytes) return {};
  return {slave_diag.data() + kStandardDiagBytes, slave_diag.size() - kStandardDiagBytes};
}

GsdMasterSlaves::GsdMasterSlaves(std::vector<GsdStationSpec> specs) {
  for (auto& spec : specs) {
    GsdMasterSlave s;
    s.outputs.assign(spec.setup.output_len, 0);
    s.spec = std::move(spec);
    slaves_.push_back(std::move(s));
  }
}

const GsdMasterSlave* GsdMasterSlaves::find(std::uint8_t address) const {
  for (const auto& s : slaves_) {
    if (s.spec.address == address) return &s;
  }
  return nullptr;
}

std::string GsdMasterSlaves::address_list() const {
  std::string s;
  for (const auto& g : slaves_) s += (s.empty() ? "" : ", ") + std::to_string(g.spec.address);
  return s.empty() ? "none" : s;
}

bool GsdMasterSlaves::healthy(const dp::master::Master& master) const {
  for (const auto& s : slaves_) {
    if (master.poll_state(s.spec.address) != dp::master::PollState::kDataExchange) return false;
  }
  return true;
}

std::error_code GsdMasterSlaves::set_outputs(dp::master::Master& master, std::uint8_t address,
                                             std::size_t slot,
                                             std::span<const std::uint8_t> bytes) {
  auto s = std::find_if(slaves_.begin(), slaves_.end(),
                        [address](const GsdMasterSlave& g) { return g.spec.address == address; });
  if (s == slaves_.end()) return std::make_error_code(std::errc::no_such_device_or_address);
  if (slot >= s->spec.modules.size()) return std::make_error_code(std::errc::result_out_of_range);
  const auto& m = s->spec.modules[slot];
  if (bytes.size() != m.output_len) return std::make_error_code(std::errc::invalid_argument);
  std::copy(bytes.begin(), bytes.end(),
            s->outputs.begin() + static_cast<std::ptrdiff_t>(m.output_offset));
  return master.set_outputs(address, s->outputs);
}

}  // namespace rs4sim::gsd
