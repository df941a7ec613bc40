#include "app/runtime/master_gsd.h"

#include "app/runtime/usage_error.h"
#include "gsd/unit_diag.h"
#include "rpc/status.h"

#include <charconv>
#include <cstdio>
#include <map>

namespace rs4sim::app {
namespace {

std::string hex_bytes(std::span<const std::uint8_t> bytes) {
  std::string s;
  char b[4];
  for (const auto x : bytes) {
    std::snprintf(b, sizeof b, "%02x", x);
    s += (s.empty() ? "" : " ") + std::string(b);
  }
  return s;
}

std::string hex16(std::uint16_t v) {
  char b[8];
  std::snprintf(b, sizeof b, "0x%04X", v);
  return b;
}

// "ADDR:REST" → (ADDR, REST); the address is decimal 0..125 ([IEC 61158-4-3 addresses, SAPs]:
// the master polls 0..125). REST is everything after the first ':', so a file name or a module
// name may hold ':' (and ',') itself.
std::pair<std::uint8_t, std::string> split_address(const std::string& option,
                                                   const std::string& value,
                                                   const char* rest_name) {
  const auto colon = value.find(':');
  int address = -1;
  const char* first = value.data();
  const char* last = value.data() + (colon == std::string::npos ? 0 : colon);
  const auto [p, ec] = std::from_chars(first, last, address);
  if (colon == std::string::npos || colon == 0 || ec != std::errc{} || p != last ||
      colon + 1 == value.size()) {
    throw UsageError(option + " " + value + ": use ADDRESS:" + rest_name + ", e.g. " +
                     (option == "--module" ? "\"5:DI 8\"" : "5:X.gsd"));
  }
  if (address < 0 || address > 125) {
    throw UsageError(option + " " + value + ": address " + std::to_string(address) +
                     " is outside 0..125 ([IEC 61158-4-3 addresses, SAPs])");
  }
  return {static_cast<std::uint8_t>(address), value.substr(colon + 1)};
}

std::string text_of(std::span<const std::uint8_t> bytes) {
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

constexpr std::size_t kStandardDiagBytes = 6;  // [IEC 61158-6-3 Slave_Diag]

// The Slave_Diag DU after its 6 standard bytes.
std::span<const std::uint8_t> ext_diag(const dp::fdl::DataUnit& diag) {
  if (diag.size() <= kStandardDiagBytes) return {};
  return {diag.data() + kStandardDiagBytes, diag.size() - kStandardDiagBytes};
}

std::string joined(const std::vector<std::string>& texts) {
  std::string out;
  for (const auto& t : texts) out += (out.empty() ? "" : "; ") + t;
  return out;
}

const char* state_name(std::optional<dp::master::PollState> s) {
  return s ? dp::master::to_string(*s) : "unknown";
}

void fill(const GsdMasterSlave& s, const dp::master::Master& master, v1::GsdMasterSlave& out) {
  const auto& spec = s.spec;
  out.set_address(spec.address);
  out.set_file(spec.file);
  out.set_ident_number(spec.device->ident_number);
  const auto inputs = master.inputs(spec.address);
  for (std::size_t i = 0; i < spec.modules.size(); ++i) {
    const auto& m = spec.modules[i];
    auto* o = out.add_modules();
    o->set_slot(static_cast<std::uint32_t>(i));
    o->set_name(m.name);
    o->set_input_length(static_cast<std::uint32_t>(m.input_len));
    o->set_output_length(static_cast<std::uint32_t>(m.output_len));
    if (m.input_offset + m.input_len <= inputs.size()) {
      o->set_inputs(text_of(inputs.subspan(m.input_offset, m.input_len)));
    }
    o->set_outputs(text_of(std::span(s.outputs).subspan(m.output_offset, m.output_len)));
  }
  const auto status = master.slave_status(spec.address);
  if (status) {
    out.set_dp_state(dp::master::to_string(status->state));
    out.set_data_exchange(status->state == dp::master::PollState::kDataExchange);
    out.set_data_exchanges(status->counters.data_exchanges);
    if (status->last_error) out.set_last_error(status->last_error.message());
    out.set_diagnosis(text_of({status->last_diag.data(), status->last_diag.size()}));
    for (auto& t : gsd::unit_diag_texts(spec.device->unit_diag, ext_diag(status->last_diag))) {
      out.add_diagnosis_texts(std::move(t));
    }
  }
  out.set_user_prm_data(text_of(spec.setup.user_prm_data));
  out.set_cfg(text_of(spec.setup.cfg));
}

std::span<const std::uint8_t> as_bytes(const std::string& s) {
  return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

}  // namespace

std::vector<GsdStationSpec> parse_gsd_slaves(const std::vector<std::string>& slaves,
                                             const std::vector<std::string>& modules,
                                             const std::string& baud,
                                             std::vector<std::string>* warnings) {
  std::vector<std::pair<std::uint8_t, std::string>> files;
  for (const auto& s : slaves) {
    auto entry = split_address("--gsd-slave", s, "FILE");
    for (const auto& [a, f] : files) {
      if (a == entry.first) {
        throw UsageError("--gsd-slave " + s + ": address " + std::to_string(a) +
                         " is already the GSD slave of " + f);
      }
    }
    files.push_back(std::move(entry));
  }
  std::map<std::uint8_t, std::vector<std::string>> chosen;
  for (const auto& m : modules) {
    auto [address, name] = split_address("--module", m, "NAME");
    bool known = false;
    for (const auto& f : files) known = known || f.first == address;
    if (!known) {
      throw UsageError("--module " + m + ": no --gsd-slave " + std::to_string(address) +
                       ":FILE given");
    }
    chosen[address].push_back(std::move(name));
  }
  std::vector<GsdStationSpec> specs;
  for (const auto& [address, file] : files) {
    specs.push_back(load_gsd_station(file, chosen[address], address, warnings));
    check_gsd_baud(specs.back(), baud);
  }
  return specs;
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

GsdMasterSlave* GsdMasterSlaves::find_mutable(std::uint8_t address) {
  return const_cast<GsdMasterSlave*>(std::as_const(*this).find(address));
}

std::string GsdMasterSlaves::address_list() const {
  std::string s;
  for (const auto& g : slaves_) s += (s.empty() ? "" : ", ") + std::to_string(g.spec.address);
  return s.empty() ? "none" : s;
}

std::vector<dp::master::SlaveEntry> GsdMasterSlaves::entries(
    std::chrono::milliseconds watchdog) const {
  std::vector<dp::master::SlaveEntry> out;
  for (const auto& s : slaves_) out.push_back(gsd_master_entry(s.spec, watchdog));
  return out;
}

void GsdMasterSlaves::start(const MasterReport& report, dp::TimePoint now) const {
  for (const auto& s : slaves_) {
    const auto& spec = s.spec;
    std::string names;
    for (const auto& m : spec.modules) {
      names += (names.empty() ? "\"" : ", \"") + m.name + (m.preset ? "\" (preset)" : "\"");
    }
    const std::string ident = hex16(spec.device->ident_number);
    report.custom(now, spec.address, "GSD slave", "gsd",
                  spec.file + ", ident " + ident + ", modules " + names + ", Chk_Cfg " +
                      hex_bytes(spec.setup.cfg) + ", User_Prm_Data " +
                      hex_bytes(spec.setup.user_prm_data),
                  {{"file", spec.file},
                   {"ident", ident},
                   {"cfg", hex_bytes(spec.setup.cfg)},
                   {"user_prm_data", hex_bytes(spec.setup.user_prm_data)},
                   {"inputs_length", static_cast<std::int64_t>(spec.setup.input_len)},
                   {"outputs_length", static_cast<std::int64_t>(spec.setup.output_len)}});
  }
}

void GsdMasterSlaves::update(const dp::master::Master& master, const MasterReport& report,
                             dp::TimePoint now) {
  for (auto& s : slaves_) {
    const std::uint8_t a = s.spec.address;
    const auto state = master.poll_state(a);
    const bool dx = state == dp::master::PollState::kDataExchange;
    const bool was_dx = s.shown_state == dp::master::PollState::kDataExchange;
    if (!s.shown_state || dx != was_dx) {
      std::vector<ReportField> f{{"state", std::string(state_name(state))},
                                 {"data_exchange", dx}};
      std::string text = dx ? "DP data exchange" : "DP start-up";
      if (const auto status = master.slave_status(a); status && !dx && status->last_error) {
        f.push_back({"reason", status->last_error.message()});
        text += " (" + status->last_error.message() + ")";
      }
      report.custom(now, a, "GSD slave", "dp", text, f);
      s.shown_state = state;
    }
    if (!s.spec.device->unit_diag.empty()) diagnosis(master, report, now, s);
    const auto in = master.inputs(a);
    if (dx && !std::equal(in.begin(), in.end(), s.shown_inputs.begin(), s.shown_inputs.end())) {
      s.shown_inputs.assign(in.begin(), in.end());
      report.custom(now, a, "GSD slave", "inputs", "inputs " + hex_bytes(in),
                    {{"inputs", hex_bytes(in)}});
    }
  }
}

// A "diagnosis" line when the device-related texts of the last Slave_Diag change.
void GsdMasterSlaves::diagnosis(const dp::master::Master& master, const MasterReport& report,
                                dp::TimePoint now, GsdMasterSlave& s) {
  const auto status = master.slave_status(s.spec.address);
  if (!status) return;
  const auto ext = ext_diag(status->last_diag);
  if (std::equal(ext.begin(), ext.end(), s.shown_diag.begin(), s.shown_diag.end())) return;
  s.shown_diag.assign(ext.begin(), ext.end());
  auto texts = joined(gsd::unit_diag_texts(s.spec.device->unit_diag, ext));
  if (texts == s.shown_diag_text) return;
  s.shown_diag_text = texts;
  report.custom(now, s.spec.address, "GSD slave", "diagnosis",
                "diagnosis " + (texts.empty() ? std::string("cleared") : texts) + " (" +
                    hex_bytes(ext) + ")",
                {{"ext_diag", hex_bytes(ext)}, {"texts", texts}});
}

void GsdMasterSlaves::stopped(const dp::master::Master& master, const MasterReport& report,
                              dp::TimePoint now) const {
  for (const auto& s : slaves_) {
    const std::uint8_t a = s.spec.address;
    const auto state = master.poll_state(a);
    const bool dx = state == dp::master::PollState::kDataExchange;
    const auto status = master.slave_status(a);
    const std::int64_t exchanges = status ? static_cast<std::int64_t>(status->counters.data_exchanges) : 0;
    report.custom(now, a, "GSD slave", "stop",
                  std::string("end: DP ") + state_name(state) + ", data exchanges " +
                      std::to_string(exchanges) + ", inputs " + hex_bytes(master.inputs(a)) +
                      ", outputs " + hex_bytes(s.outputs),
                  {{"dp", std::string(state_name(state))},
                   {"data_exchange", dx},
                   {"data_exchanges", exchanges},
                   {"inputs", hex_bytes(master.inputs(a))},
                   {"outputs", hex_bytes(s.outputs)}});
  }
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
  GsdMasterSlave* s = find_mutable(address);
  if (s == nullptr) return std::make_error_code(std::errc::no_such_device_or_address);
  if (slot >= s->spec.modules.size()) return std::make_error_code(std::errc::result_out_of_range);
  const auto& m = s->spec.modules[slot];
  if (bytes.size() != m.output_len) return std::make_error_code(std::errc::invalid_argument);
  std::copy(bytes.begin(), bytes.end(), s->outputs.begin() + static_cast<std::ptrdiff_t>(m.output_offset));
  return master.set_outputs(address, s->outputs);
}

// ---- rs4sim.v1.GsdMaster --------------------------------------------------------------------

grpc::Status GsdMasterService::ListSlaves(grpc::ServerContext*, const v1::Empty*,
                                          v1::ListGsdMasterSlavesResponse* out) {
  executor_.run([&] {
    for (const auto& s : slaves_.slaves()) fill(s, master_(), *out->add_slaves());
  });
  return grpc::Status::OK;
}

grpc::Status GsdMasterService::GetSlave(grpc::ServerContext*, const v1::StationRequest* in,
                                        v1::GsdMasterSlave* out) {
  grpc::Status result;
  executor_.run([&] {
    const auto* s = in->address() <= 125 ? slaves_.find(static_cast<std::uint8_t>(in->address()))
                                         : nullptr;
    if (s == nullptr) {
      result = rpc::not_found("no GSD slave at address " + std::to_string(in->address()) +
                              " (this master's GSD slaves: " + slaves_.address_list() + ")");
      return;
    }
    fill(*s, master_(), *out);
  });
  return result;
}

grpc::Status GsdMasterService::SetOutputs(grpc::ServerContext*,
                                          const v1::SetGsdOutputsRequest* in, v1::Empty*) {
  grpc::Status result;
  executor_.run([&] {
    const auto* s = in->address() <= 125 ? slaves_.find(static_cast<std::uint8_t>(in->address()))
                                         : nullptr;
    if (s == nullptr) {
      result = rpc::not_found("no GSD slave at address " + std::to_string(in->address()) +
                              " (this master's GSD slaves: " + slaves_.address_list() + ")");
      return;
    }
    const auto& modules = s->spec.modules;
    if (in->slot() >= modules.size()) {
      result = rpc::invalid_argument(
          "slot", "slot " + std::to_string(in->slot()) + " outside 0.." +
                      std::to_string(modules.size() - 1) + " (the slave's " +
                      std::to_string(modules.size()) + " modules)");
      return;
    }
    const auto& m = modules[in->slot()];
    if (in->data().size() != m.output_len) {
      result = rpc::invalid_argument(
          "data", std::to_string(in->data().size()) + " bytes; module \"" + m.name + "\" (slot " +
                      std::to_string(in->slot()) + ") has " + std::to_string(m.output_len) +
                      " output bytes");
      return;
    }
    if (auto e = slaves_.set_outputs(master_(), s->spec.address, in->slot(), as_bytes(in->data()))) {
      result = rpc::failed_precondition("MASTER", "slave " + std::to_string(s->spec.address),
                                        "the master refused the outputs: " + e.message());
    }
  });
  return result;
}

}  // namespace rs4sim::app
