#include "gsd/station/gsd_master_slaves.h"

#include "gsd/f_module.h"

#include <algorithm>

namespace rs4sim::gsd {

std::span<const std::uint8_t> ext_diagnosis(const dp::fdl::DataUnit& slave_diag) {
  constexpr std::size_t kStandardDiagBytes = 6;  // [IEC 61158-6-3 Slave_Diag]
  if (slave_diag.size() <= kStandardDiagBytes) return {};
  return {slave_diag.data() + kStandardDiagBytes, slave_diag.size() - kStandardDiagBytes};
}

// ---- errors ---------------------------------------------------------------------------------

namespace {

class FModuleCategory final : public std::error_category {
 public:
  [[nodiscard]] const char* name() const noexcept override { return "gsd-f-module"; }
  [[nodiscard]] std::string message(int e) const override {
    switch (static_cast<FModuleError>(e)) {
      case FModuleError::kNoSlave: return "no GSD slave at that address";
      case FModuleError::kNotFModule: return "the slot holds no F-module with our F-host";
      case FModuleError::kWrongLength: return "not the module's F-data length";
      case FModuleError::kNothingWaits: return "no ACK_REQ waits for an acknowledgement";
    }
    return "unknown";
  }
};

}  // namespace

const std::error_category& f_module_category() noexcept {
  static const FModuleCategory category;
  return category;
}

std::error_code make_error_code(FModuleError e) noexcept {
  return {static_cast<int>(e), f_module_category()};
}

// ---- F-modules --------------------------------------------------------------------------------

GsdMasterFModule::GsdMasterFModule(std::size_t module, const profisafe::FHostConfig& config,
                                   std::size_t input, std::size_t output)
    : slot(module),
      input_offset(input),
      output_offset(output),
      pdu_size(profisafe::pdu_size(
          profisafe::PduConfig::from(config.params, config.data_size, config.crc2_variant))),
      parameters(config.params),
      host(config),
      f_outputs(config.data_size, 0),
      sent(config.data_size, 0) {}

const char* GsdMasterFModule::mode() const noexcept {
  return host.version() == profisafe::ProtocolVersion::kV2 ? "V2" : "V1";
}

const GsdMasterFModule* GsdMasterSlave::f_module(std::size_t slot) const {
  for (const auto& f : f_modules) {
    if (f.slot == slot) return &f;
  }
  return nullptr;
}

std::string GsdMasterSlave::f_slot_list() const {
  std::string s;
  for (const auto& f : f_modules) s += (s.empty() ? "" : ", ") + std::to_string(f.slot);
  return s.empty() ? "none" : s;
}

namespace {

// The F-module of `block` with our F-host, its F-parameter block written into the spec's
// User_Prm_Data ([IEC 61784-3-3 F-Parameters]: F_Par_CRC = CRC1 over the 8 bytes before it);
// nullopt when our F-host cannot serve its F-data.
std::optional<GsdMasterFModule> host_for(GsdStationSpec& spec, const FParameterBlock& block) {
  const Module& m = spec.device->modules[spec.setup.slots[block.module].index];
  const auto info = describe_f_module(*spec.device, m);
  if (!info) return std::nullopt;
  const std::size_t size = info.value().io.f_input_bytes;
  if (size != info.value().io.f_output_bytes || size == 0 || size > profisafe::kMaxDataSize) {
    return std::nullopt;
  }
  profisafe::FParameters p = block.parameters;
  if (spec.f_dest_add) p.dest_add = *spec.f_dest_add;
  if (!profisafe::is_supported_connection(p.par_version, p.crc_length)) return std::nullopt;
  p.par_crc = profisafe::crc1(p);
  const auto encoded = profisafe::encode_f_parameters(p);
  std::copy(encoded.begin(), encoded.end(),
            spec.setup.user_prm_data.begin() + static_cast<std::ptrdiff_t>(block.offset));
  const auto& io = spec.modules.at(block.module);
  return GsdMasterFModule(block.module, profisafe::FHostConfig{p, size, {}}, io.input_offset,
                          io.output_offset);
}

}  // namespace

GsdMasterSlaves::GsdMasterSlaves(std::vector<GsdStationSpec> specs) {
  for (auto& spec : specs) {
    GsdMasterSlave s;
    s.outputs.assign(spec.setup.output_len, 0);
    for (const auto& block : spec.setup.f_parameters) {
      if (auto f = host_for(spec, block)) s.f_modules.push_back(std::move(*f));
    }
    f_module_count_ += s.f_modules.size();
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

GsdMasterSlave* GsdMasterSlaves::find_mutable(std::uint8_t address) {
  return const_cast<GsdMasterSlave*>(find(address));
}

std::string GsdMasterSlaves::address_list() const {
  std::string s;
  for (const auto& g : slaves_) s += (s.empty() ? "" : ", ") + std::to_string(g.spec.address);
  return s.empty() ? "none" : s;
}

bool GsdMasterSlaves::healthy(const dp::master::Master& master) const {
  for (const auto& s : slaves_) {
    if (master.poll_state(s.spec.address) != dp::master::PollState::kDataExchange) return false;
    for (const auto& f : s.f_modules) {
      if (f.host.state() != profisafe::FHostState::kRun) return false;
    }
  }
  return true;
}

std::error_code GsdMasterSlaves::set_outputs(dp::master::Master& master, std::uint8_t address,
                                             std::size_t slot,
                                             std::span<const std::uint8_t> bytes) {
  GsdMasterSlave* s = find_mutable(address);
  if (s == nullptr) return std::make_error_code(std::errc::no_such_device_or_address);
  if (slot >= s->spec.modules.size()) return std::make_error_code(std::errc::result_out_of_range);
  if (s->f_module(slot) != nullptr) return std::make_error_code(std::errc::operation_not_permitted);
  const auto& m = s->spec.modules[slot];
  if (bytes.size() != m.output_len) return std::make_error_code(std::errc::invalid_argument);
  std::copy(bytes.begin(), bytes.end(),
            s->outputs.begin() + static_cast<std::ptrdiff_t>(m.output_offset));
  return master.set_outputs(address, s->outputs);
}

// ---- the F-hosts ------------------------------------------------------------------------------

namespace {

// The words the API and the report give a fault that passivated an F-host.
const char* fault_text(profisafe::FHostEvent e, std::uint8_t status) {
  switch (e) {
    case profisafe::FHostEvent::kCrcError: return "CRC2 error";
    case profisafe::FHostEvent::kNumberError: return "consecutive number error";
    case profisafe::FHostEvent::kDeviceFault:
      return (status & profisafe::status_bit::kCeCrc) != 0 ? "device reported CE_CRC"
                                                           : "device reported WD_timeout";
    default: return "";
  }
}

}  // namespace

// One step of [PROFIsafe V1.30 F-Device behaviour]: the device's PDU of the last Data_Exchange
// in, the watchdog, the next PDU out (only in data exchange: the watchdog runs on while the
// slave is away, so a lost slave passivates its F-host). Returns whether the state changed.
bool GsdMasterSlaves::safety_step(GsdMasterFModule& f, std::span<const std::uint8_t> inputs,
                                  bool dx, dp::TimePoint now) {
  const auto before = f.host.state();
  const auto timeouts = f.host.counters().watchdog_timeouts;
  // A fault in start-up (the device's first answers) passivates nothing that ran: not shown.
  const bool started = before != profisafe::FHostState::kStartup;
  if (dx && inputs.size() >= f.input_offset + f.pdu_size) {
    const auto e = f.host.on_pdu(inputs.subspan(f.input_offset, f.pdu_size), now);
    const char* text = fault_text(e, f.host.last_status());
    if (started && *text != '\0') f.last_fault = text;
  }
  f.host.on_time(now);
  if (started && f.host.counters().watchdog_timeouts != timeouts) {
    f.last_fault = "watchdog F_WD_Time expired";
  }
  return f.host.state() != before;
}

bool GsdMasterSlaves::on_master_cycle(dp::master::Master& master, dp::TimePoint now,
                                      bool auto_ack) {
  bool changed = false;
  for (auto& s : slaves_) {
    if (s.f_modules.empty()) continue;
    const std::uint8_t a = s.spec.address;
    const bool dx = master.poll_state(a) == dp::master::PollState::kDataExchange;
    const auto inputs = master.inputs(a);
    for (auto& f : s.f_modules) {
      changed = safety_step(f, inputs, dx, now) || changed;
      if (auto_ack && f.host.ack_req()) {
        f.host.ack_rei();
        changed = true;
      }
      if (!dx) continue;
      const auto pdu = f.host.request(now);  // empty while muted: the old bytes go out again
      if (pdu.size() != f.pdu_size) continue;
      std::copy(pdu.begin(), pdu.end(),
                s.outputs.begin() + static_cast<std::ptrdiff_t>(f.output_offset));
      std::copy(pdu.begin(), pdu.begin() + static_cast<std::ptrdiff_t>(f.f_data_size()),
                f.sent.begin());
    }
    if (dx) (void)master.set_outputs(a, s.outputs);
  }
  return changed;
}

std::error_code GsdMasterSlaves::f_module(std::uint8_t address, std::size_t slot,
                                          GsdMasterFModule*& out) {
  GsdMasterSlave* s = find_mutable(address);
  if (s == nullptr) return FModuleError::kNoSlave;
  for (auto& f : s->f_modules) {
    if (f.slot == slot) {
      out = &f;
      return {};
    }
  }
  return FModuleError::kNotFModule;
}

std::error_code GsdMasterSlaves::set_f_outputs(std::uint8_t address, std::size_t slot,
                                               std::span<const std::uint8_t> data) {
  GsdMasterFModule* f = nullptr;
  if (auto e = f_module(address, slot, f)) return e;
  if (data.size() != f->f_data_size()) return FModuleError::kWrongLength;
  std::copy(data.begin(), data.end(), f->f_outputs.begin());
  f->host.set_output(data);
  return {};
}

std::error_code GsdMasterSlaves::acknowledge(std::uint8_t address, std::size_t slot) {
  GsdMasterFModule* f = nullptr;
  if (auto e = f_module(address, slot, f)) return e;
  if (!f->host.ack_req()) return FModuleError::kNothingWaits;
  f->host.ack_rei();
  return {};
}

}  // namespace rs4sim::gsd
