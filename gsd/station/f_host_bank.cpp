// Our master's F-hosts for GSD stations' F-modules. See f_host_bank.h.
#include "gsd/station/f_host_bank.h"

#include <algorithm>

namespace rs4sim::gsd {

FHostBank::FHostBank(const std::vector<const GsdStation*>& stations) {
  for (const GsdStation* s : stations) {
    const GsdStationSpec& spec = s->spec();
    for (const FModuleDevice& f : s->application().f_modules()) {
      const auto& blocks = spec.setup.f_parameters;
      const auto block = std::find_if(blocks.begin(), blocks.end(), [&f](const FParameterBlock& b) {
        return b.module == f.module();
      });
      if (block == spec.setup.f_parameters.end()) continue;
      const auto& io = spec.modules[f.module()];
      const auto pdu = profisafe::pdu_size(
          profisafe::PduConfig::from(block->parameters, f.f_data_size()));
      hosts_.push_back({s->address(), f.module(), io.input_offset, io.output_offset, pdu,
                        profisafe::FHost({block->parameters, f.f_data_size(), {}}),
                        std::vector<std::uint8_t>(f.f_data_size(), 0)});
    }
    if (!s->application().f_modules().empty()) {
      images_.push_back({s->address(), std::vector<std::uint8_t>(spec.setup.output_len, 0)});
    }
  }
}

// [IEC 61784-3-3 F-Host behaviour]: the device's answer first, then the host's own watchdog,
// then the next request (only in data exchange: out of it the master sends nothing).
void FHostBank::cycle(dp::master::Master& master, dp::TimePoint now) {
  for (Image& image : images_) {
    const bool dx = master.poll_state(image.address) == dp::master::PollState::kDataExchange;
    const auto in = master.inputs(image.address);
    for (Host& h : hosts_) {
      if (h.address != image.address) continue;
      if (dx && in.size() >= h.input_offset + h.pdu_size) {
        (void)h.host.on_pdu(in.subspan(h.input_offset, h.pdu_size), now);
      }
      h.host.on_time(now);
      if (!dx) continue;
      const auto out = h.host.request(now);
      std::copy(out.begin(), out.end(),
                image.outputs.begin() + static_cast<std::ptrdiff_t>(h.output_offset));
    }
    if (dx) (void)master.set_outputs(image.address, image.outputs);
  }
}

const FHostBank::Host* FHostBank::host(std::uint8_t address, std::size_t module) const {
  for (const Host& h : hosts_) {
    if (h.address == address && h.module == module) return &h;
  }
  return nullptr;
}

profisafe::FHost* FHostBank::find(std::uint8_t address, std::size_t module) {
  const Host* h = host(address, module);
  return h != nullptr ? &const_cast<Host*>(h)->host : nullptr;
}

const profisafe::FHost* FHostBank::find(std::uint8_t address, std::size_t module) const {
  const Host* h = host(address, module);
  return h != nullptr ? &h->host : nullptr;
}

bool FHostBank::set_output(std::uint8_t address, std::size_t module,
                           std::span<const std::uint8_t> data) {
  auto* h = const_cast<Host*>(host(address, module));
  if (h == nullptr || data.size() != h->output.size()) return false;
  h->output.assign(data.begin(), data.end());
  h->host.set_output(data);
  return true;
}

std::span<const std::uint8_t> FHostBank::output(std::uint8_t address, std::size_t module) const {
  const Host* h = host(address, module);
  return h != nullptr ? std::span<const std::uint8_t>(h->output) : std::span<const std::uint8_t>{};
}

}  // namespace rs4sim::gsd
