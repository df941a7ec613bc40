#pragma once
// What rs4sim.v1.GsdStations and rs4sim.v1.GsdMaster both say of a GSD station or slave
// (gsd.proto: GsdStation and GsdMasterSlave, GsdModule and GsdMasterModule have the same
// fields): its file, ident and modules, each with its bytes of the I/O images (the address is
// the caller's: a station's own may have changed by Set_Slave_Add).

#include "gsd/station/gsd_station.h"

#include <cstdint>
#include <span>
#include <string>

namespace rs4sim::rpc {

// `inputs` and `outputs` are the station's whole images. A module beyond a shorter image: no
// inputs, its outputs zeros (before the first Data_Exchange the master wrote nothing).
template <class Message>
void fill_gsd_station(const gsd::GsdStationSpec& spec, std::span<const std::uint8_t> inputs,
                      std::span<const std::uint8_t> outputs, Message& out) {
  out.set_file(spec.file);
  out.set_ident_number(spec.device->ident_number);
  for (std::size_t i = 0; i < spec.modules.size(); ++i) {
    const auto& m = spec.modules[i];
    auto* o = out.add_modules();
    o->set_slot(static_cast<std::uint32_t>(i));
    o->set_name(m.name);
    o->set_input_length(static_cast<std::uint32_t>(m.input_len));
    o->set_output_length(static_cast<std::uint32_t>(m.output_len));
    if (m.input_offset + m.input_len <= inputs.size()) {
      o->set_inputs(inputs.data() + m.input_offset, m.input_len);
    }
    std::string bytes(m.output_len, '\0');
    if (m.output_offset + m.output_len <= outputs.size()) {
      bytes.assign(reinterpret_cast<const char*>(outputs.data() + m.output_offset), m.output_len);
    }
    o->set_outputs(bytes);
  }
}

}  // namespace rs4sim::rpc
