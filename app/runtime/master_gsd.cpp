#include "app/runtime/master_gsd.h"

#include "app/devices/bus_file.h"
#include "app/runtime/usage_error.h"
#include "gsd/check_report.h"
#include "gsd/syntax.h"

#include <algorithm>
#include <charconv>
#include <map>

namespace rs4sim::app {
namespace {

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
                     (option == "--module"             ? "\"5:DI 8\""
                      : option == "--gsd-f-dest-add" ? "5:300"
                                                     : "5:X.gsd"));
  }
  if (address < 0 || address > 125) {
    throw UsageError(option + " " + value + ": address " + std::to_string(address) +
                     " is outside 0..125 ([IEC 61158-4-3 addresses, SAPs])");
  }
  return {static_cast<std::uint8_t>(address), value.substr(colon + 1)};
}

// The slave's inputs as the program sees them: an F-module's safety PDU (whose consecutive number
// and CRC2 change every cycle) replaced by the F-input data of its F-host, 0 while passivated.
// `out` is reused from call to call (no allocation per link call).
std::span<const std::uint8_t> process_inputs(std::span<const std::uint8_t> in,
                                             const gsd::GsdMasterSlave& s,
                                             std::vector<std::uint8_t>& out) {
  if (s.f_modules.empty()) return in;
  out.assign(in.begin(), in.end());
  for (const auto& f : s.f_modules) {
    if (out.size() < f.input_offset + f.pdu_size) continue;
    const auto data = f.host.input();
    const auto at = out.begin() + static_cast<std::ptrdiff_t>(f.input_offset);
    std::fill(at, at + static_cast<std::ptrdiff_t>(f.pdu_size), std::uint8_t{0});
    std::copy(data.begin(), data.end(), at);
  }
  return out;
}

const char* state_name(std::optional<dp::master::PollState> s) {
  return s ? dp::master::to_string(*s) : "unknown";
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

void apply_gsd_f_dest_adds(std::vector<GsdStationSpec>& specs,
                           const std::vector<std::string>& values) {
  for (const auto& v : values) {
    auto [address, number] = split_address("--gsd-f-dest-add", v, "F_DEST_ADD");
    int value = 0;
    const auto [p, ec] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (ec != std::errc{} || p != number.data() + number.size()) {
      throw UsageError("--gsd-f-dest-add " + v + ": \"" + number + "\" is not a decimal number");
    }
    auto it = std::find_if(specs.begin(), specs.end(),
                           [a = address](const GsdStationSpec& s) { return s.address == a; });
    if (it == specs.end()) {
      throw UsageError("--gsd-f-dest-add " + v + ": no --gsd-slave " + std::to_string(address) +
                       ":FILE given");
    }
    it->f_dest_add = check_f_dest_add(*it, value);
  }
}

void apply_gsd_f_wd_time(std::vector<GsdStationSpec>& specs, int ms) {
  for (auto& spec : specs) {
    for (const auto& [number, p] : spec.device->params) {
      if (!spec.setup.f_parameters.empty() && gsd::syntax::iequals(p.name, "F_WD_Time") &&
          !p.accepts(ms)) {
        throw UsageError("--f-wd-time " + std::to_string(ms) + ": " + spec.file + ":" +
                         std::to_string(p.line) + ": F_WD_Time is " + p.range_text() +
                         " for GSD slave " + std::to_string(spec.address));
      }
    }
    for (auto& block : spec.setup.f_parameters) {
      block.parameters.wd_time_ms = static_cast<std::uint16_t>(ms);
    }
  }
}

MasterBusFile read_master_bus_file(const std::string& file, const std::string& baud) {
  const BusFile bus = read_bus_file(file, baud);
  MasterBusFile out;
  for (const auto& s : bus.stations) {
    const DeviceOptions& o = s.options;
    if (s.kind == stream::DeviceKind::kRs4 && o.gsd.empty()) {
      out.rs4s.push_back(*o.address);
    } else if (s.kind == stream::DeviceKind::kGeneric && !o.gsd.empty()) {
      out.gsd.push_back(load_gsd_station(o.gsd, o.modules, *o.address));
      check_gsd_baud(out.gsd.back(), baud);
      if (o.f_dest_add) out.gsd.back().f_dest_add = check_f_dest_add(out.gsd.back(), *o.f_dest_add);
    } else {
      throw UsageError(file + ": " + s.path +
                       ": our master configures an RS4 from its built-in GSD and other slaves "
                       "from their \"gsd\" file; this station is neither");
    }
  }
  return out;
}

void GsdMasterReport::start(const MasterReport& report, dp::TimePoint now) const {
  for (const auto& s : slaves_.slaves()) {
    const auto& spec = s.spec;
    std::string names;
    for (const auto& m : spec.modules) {
      names += (names.empty() ? "\"" : ", \"") + m.name + (m.preset ? "\" (preset)" : "\"");
    }
    const std::string ident = gsd::hex16(spec.device->ident_number);
    report.custom(now, spec.address, "GSD slave", "gsd",
                  spec.file + ", ident " + ident + ", modules " + names + ", Chk_Cfg " +
                      gsd::io_hex(spec.setup.cfg) + ", User_Prm_Data " +
                      gsd::io_hex(spec.setup.user_prm_data),
                  {{"file", spec.file},
                   {"ident", ident},
                   {"cfg", gsd::io_hex(spec.setup.cfg)},
                   {"user_prm_data", gsd::io_hex(spec.setup.user_prm_data)},
                   {"inputs_length", static_cast<std::int64_t>(spec.setup.input_len)},
                   {"outputs_length", static_cast<std::int64_t>(spec.setup.output_len)}});
  }
}

void GsdMasterReport::update(const dp::master::Master& master, const MasterReport& report,
                             dp::TimePoint now) {
  for (std::size_t i = 0; i < shown_.size(); ++i) {
    const auto& s = slaves_.slaves()[i];
    auto& shown = shown_[i];
    const std::uint8_t a = s.spec.address;
    const auto state = master.poll_state(a);
    const bool dx = state == dp::master::PollState::kDataExchange;
    const bool was_dx = shown.state == dp::master::PollState::kDataExchange;
    if (!shown.state || dx != was_dx) {
      std::vector<ReportField> f{{"state", std::string(state_name(state))}, {"data_exchange", dx}};
      std::string text = dx ? "DP data exchange" : "DP start-up";
      if (const auto status = master.slave_status(a); status && !dx && status->last_error) {
        f.push_back({"reason", status->last_error.message()});
        text += " (" + status->last_error.message() + ")";
      }
      report.custom(now, a, "GSD slave", "dp", text, f);
      shown.state = state;
    }
    if (!s.spec.device->unit_diag.empty()) diagnosis(master, report, now, s, shown);
    if (!s.f_modules.empty()) f_modules(report, now, s, shown);
    const auto in = process_inputs(master.inputs(a), s, scratch_);
    if (dx && !std::equal(in.begin(), in.end(), shown.inputs.begin(), shown.inputs.end())) {
      shown.inputs.assign(in.begin(), in.end());
      report.custom(now, a, "GSD slave", "inputs", "inputs " + gsd::io_hex(in),
                    {{"inputs", gsd::io_hex(in)}});
    }
  }
}

// A "diagnosis" line when the device-related texts of the last Slave_Diag change.
void GsdMasterReport::diagnosis(const dp::master::Master& master, const MasterReport& report,
                                dp::TimePoint now, const gsd::GsdMasterSlave& s, Shown& shown) {
  const auto status = master.slave_status(s.spec.address);
  if (!status) return;
  const auto ext = gsd::ext_diagnosis(status->last_diag);
  if (std::equal(ext.begin(), ext.end(), shown.diag.begin(), shown.diag.end())) return;
  shown.diag.assign(ext.begin(), ext.end());
  auto texts = gsd::diagnosis_text(*s.spec.device, ext);
  if (texts == shown.diag_text) return;
  shown.diag_text = texts;
  report.custom(now, s.spec.address, "GSD slave", "diagnosis",
                "diagnosis " + (texts.empty() ? std::string("cleared") : texts) + " (" +
                    gsd::io_hex(ext) + ")",
                {{"ext_diag", gsd::io_hex(ext)}, {"texts", texts}});
}

// A "profisafe" line per F-module whose F-host changed its state (with the fault that
// passivated it).
void GsdMasterReport::f_modules(const MasterReport& report, dp::TimePoint now,
                                const gsd::GsdMasterSlave& s, Shown& shown) {
  shown.f_states.resize(s.f_modules.size());
  for (std::size_t i = 0; i < s.f_modules.size(); ++i) {
    const auto& f = s.f_modules[i];
    const auto state = f.host.state();
    if (shown.f_states[i] == state) continue;
    shown.f_states[i] = state;
    const std::string token(profisafe::to_token(state));
    std::string text = std::string("PROFIsafe ") + f.mode() + " slot " + std::to_string(f.slot) +
                       ": " + token;
    if (state != profisafe::FHostState::kRun && !f.last_fault.empty()) {
      text += " (" + f.last_fault + ")";
    }
    report.custom(now, s.spec.address, "GSD slave", "profisafe", text,
                  {{"slot", static_cast<std::int64_t>(f.slot)},
                   {"mode", std::string(f.mode())},
                   {"state", token},
                   {"passivated", f.host.passivated()},
                   {"ack_req", f.host.ack_req()},
                   {"last_fault", f.last_fault}});
  }
}

void GsdMasterReport::stopped(const dp::master::Master& master, const MasterReport& report,
                              dp::TimePoint now) const {
  for (const auto& s : slaves_.slaves()) {
    const std::uint8_t a = s.spec.address;
    const auto state = master.poll_state(a);
    const bool dx = state == dp::master::PollState::kDataExchange;
    const auto status = master.slave_status(a);
    const std::int64_t exchanges =
        status ? static_cast<std::int64_t>(status->counters.data_exchanges) : 0;
    // Each F-module's F-host: "slot 0 V1 run" ("; "-separated).
    std::string f_states;
    for (const auto& f : s.f_modules) {
      f_states += (f_states.empty() ? "" : "; ") + std::string("slot ") + std::to_string(f.slot) +
                  " " + f.mode() + " " + std::string(profisafe::to_token(f.host.state()));
    }
    report.custom(now, a, "GSD slave", "stop",
                  std::string("end: DP ") + state_name(state) + ", data exchanges " +
                      std::to_string(exchanges) + ", inputs " + gsd::io_hex(master.inputs(a)) +
                      ", outputs " + gsd::io_hex(s.outputs) +
                      (f_states.empty() ? "" : ", PROFIsafe " + f_states),
                  {{"dp", std::string(state_name(state))},
                   {"data_exchange", dx},
                   {"data_exchanges", exchanges},
                   {"inputs", gsd::io_hex(master.inputs(a))},
                   {"outputs", gsd::io_hex(s.outputs)},
                   {"profisafe", f_states}});
  }
}

}  // namespace rs4sim::app
