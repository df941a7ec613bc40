// `rs4sim gsd`: print the virtual RS4/PROFIsafe's GSD file, or (--prm) the Set_Prm user
// data and Chk_Cfg bytes a master needs — for masters that cannot read GSD files.
// The layout of the user data is documented in docs/gsd.md.
#include "app/cli/command.h"
#include "app/runtime/whole_file.h"
#include "gsd/check_report.h"
#include "gsd/config.h"
#include "gsd/device_gsd.h"
#include "gsd/f_module.h"
#include "gsd/interp.h"
#include "rs4/report/json_writer.h"
#include "rs4/safety/profile.h"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>

namespace rs4sim::app {
namespace {

struct Options {
  std::string output;
  bool prm = false;
  bool json = false;
  std::optional<unsigned> address;
  std::optional<unsigned> f_source_add;
  std::optional<unsigned> f_wd_time;
  bool f_check_seqnr = false;
  std::string gsd_file;
  std::vector<std::string> modules;
  std::vector<std::string> sets;
  std::string check_file;  // `gsd check FILE`
  CLI::App* check = nullptr;
};

using gsd::hex16;
using gsd::hex_bytes;

gsd::ParamOverride parse_set(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size()) {
    throw UsageError("--set expects NAME=VALUE, got '" + text + "'");
  }
  const std::string value = text.substr(eq + 1);
  std::size_t used = 0;
  long long v = 0;
  try {
    v = std::stoll(value, &used, 0);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != value.size()) throw UsageError("--set " + text + ": '" + value + "' is not a number");
  return {text.substr(0, eq), v};
}

// One line per User_Prm_Data byte: offset, value and what lies in it.
std::string byte_notes(const gsd::SlaveSetup& c, std::size_t i) {
  std::string notes;
  if (c.dpv1 && i < 3) notes = "DPV1_Status_" + std::to_string(i + 1);
  for (const auto& f : c.fields) {
    const std::size_t n = gsd::byte_size(f.type);
    if (i < f.offset || i >= f.offset + n) continue;
    std::string note = f.name + "=" + std::to_string(f.value);
    if (n > 1) note += " (byte " + std::to_string(i - f.offset + 1) + "/" + std::to_string(n) + ")";
    notes += (notes.empty() ? "" : ", ") + note;
  }
  return notes.empty() ? "constant" : notes;
}

void print_text(const gsd::SlaveSetup& c, const std::string& source, std::ostream& out) {
  out << "GSD: " << source << "\n";
  out << "Ident_Number: " << hex16(c.ident_number) << "\n";
  for (std::size_t i = 0; i < c.modules.size(); ++i) {
    out << "Module: " << c.modules[i] << " (slot " << c.slots[i].slot
        << (c.slots[i].preset ? ", preset" : "") << ")\n";
  }
  out << "Chk_Cfg: " << hex_bytes(c.cfg) << "\n";
  out << "Input_Len: " << c.input_len << "\n";
  out << "Output_Len: " << c.output_len << "\n";
  out << "User_Prm_Data: " << hex_bytes(c.user_prm_data) << "\n";
  for (std::size_t i = 0; i < c.user_prm_data.size(); ++i) {
    char b[32];
    std::snprintf(b, sizeof b, "  +%-3zu %02X  ", i, c.user_prm_data[i]);
    out << b << byte_notes(c, i) << "\n";
  }
  for (const auto& f : c.f_parameters) {
    out << "F_Par_CRC (CRC1) of module " << f.module + 1 << ": " << hex16(f.parameters.par_crc)
        << "\n";
  }
}

// Per F-module: the safety I/O its F-parameters select and where its block lies.
void print_f_modules(const gsd::Device& d, const gsd::SlaveSetup& c, std::ostream& out) {
  for (const auto& f : c.f_parameters) {
    const gsd::Module& m = d.modules[c.slots[f.module].index];
    const auto io = gsd::safety_io_layout(m, f.parameters);
    const auto block = std::vector<std::uint8_t>(
        c.user_prm_data.begin() + static_cast<std::ptrdiff_t>(f.offset),
        c.user_prm_data.begin() + static_cast<std::ptrdiff_t>(f.offset + 10));
    out << "F-module " << f.module + 1 << " (" << m.name
        << "): " << (io ? gsd::to_text(io.value()) : io.error().message) << "\n  F-parameters at +"
        << f.offset << ": " << hex_bytes(block) << "\n";
  }
}

// "f_modules": the safety I/O of each F-module (gsd::safety_io_layout).
void json_f_modules(const gsd::Device& d, const gsd::SlaveSetup& c, std::ostream& out) {
  out << ",\n  \"f_modules\": [";
  for (std::size_t i = 0; i < c.f_parameters.size(); ++i) {
    const auto& f = c.f_parameters[i];
    const gsd::Module& m = d.modules[c.slots[f.module].index];
    const auto io = gsd::safety_io_layout(m, f.parameters);
    out << (i ? ",\n    " : "\n    ") << "{\"module\": " << f.module + 1
        << ", \"offset\": " << f.offset;
    if (io) {
      out << ", \"version\": " << (io.value().version == profisafe::ProtocolVersion::kV1 ? 1 : 2)
          << ", \"crc2_bytes\": " << io.value().crc2_bytes
          << ", \"f_input_bytes\": " << io.value().f_input_bytes
          << ", \"f_output_bytes\": " << io.value().f_output_bytes;
    }
    out << "}";
  }
  out << "\n  ]";
}

void print_json(const gsd::Device& d, const gsd::SlaveSetup& c, const std::string& source,
                std::ostream& out) {
  out << "{\n  \"gsd\": " << rs4::report::json_quote(source) << ",\n";
  out << "  \"ident_number\": " << rs4::report::json_quote(hex16(c.ident_number)) << ",\n";
  out << "  \"modules\": [";
  for (std::size_t i = 0; i < c.modules.size(); ++i)
    out << (i ? ", " : "") << rs4::report::json_quote(c.modules[i]);
  out << "],\n  \"chk_cfg\": " << rs4::report::json_quote(hex_bytes(c.cfg)) << ",\n";
  out << "  \"input_len\": " << c.input_len << ",\n  \"output_len\": " << c.output_len << ",\n";
  out << "  \"user_prm_data\": " << rs4::report::json_quote(hex_bytes(c.user_prm_data)) << ",\n";
  out << "  \"parameters\": [";
  for (std::size_t i = 0; i < c.fields.size(); ++i) {
    const auto& f = c.fields[i];
    out << (i ? ",\n    " : "\n    ") << "{\"name\": " << rs4::report::json_quote(f.name)
        << ", \"offset\": " << f.offset << ", \"value\": " << f.value << "}";
  }
  out << "\n  ],\n  \"f_par_crc\": [";
  for (std::size_t i = 0; i < c.f_parameters.size(); ++i) {
    out << (i ? ", " : "") << rs4::report::json_quote(hex16(c.f_parameters[i].parameters.par_crc));
  }
  out << "]";
  json_f_modules(d, c, out);
  out << "\n}\n";
}

std::vector<gsd::ParamOverride> overrides(const Options& o, bool builtin) {
  std::vector<gsd::ParamOverride> list;
  if (o.address && builtin) list.push_back({"F_Dest_Add", rs4::safety::f_dest_add(*o.address)});
  if (o.f_source_add) list.push_back({"F_Source_Add", *o.f_source_add});
  if (o.f_wd_time) list.push_back({"F_WD_Time", *o.f_wd_time});
  if (o.f_check_seqnr) list.push_back({"F_Check_SeqNr", 1});
  for (const auto& s : o.sets) list.push_back(parse_set(s));
  return list;
}

int run_prm(const Options& o) {
  const bool builtin = o.gsd_file.empty();
  gsd::Result<gsd::Device> loaded = gsd::Error{};
  if (!builtin) {
    const auto file = read_whole_file(o.gsd_file);
    if (!file) {
      std::cerr << "rs4sim gsd: cannot read " << o.gsd_file << ": " << file.error << "\n";
      return 2;
    }
    loaded = gsd::parse(file.bytes, o.gsd_file);
  }
  const gsd::Result<gsd::Device>& device = builtin ? gsd::rs4sim_device() : loaded;
  if (!device) {  // the user's file refused: bad input (the built-in file never is)
    std::cerr << "rs4sim gsd: " << device.error().what() << "\n";
    return 2;
  }
  for (const auto& w : device.value().warnings) {
    std::cerr << "rs4sim gsd: warning: " << w.what() << "\n";
  }
  auto config = gsd::configure(device.value(), {o.modules, overrides(o, builtin)});
  if (!config) {  // a module the file does not have: bad input; a parameter value: 1
    std::cerr << "rs4sim gsd: " << config.error().what() << "\n";
    const auto code = config.error().code;
    return code == gsd::GsdError::kUnknownModule || code == gsd::GsdError::kModuleCount ? 2 : 1;
  }
  const std::string source =
      builtin ? std::string(gsd::kRs4simGsdFileName) + " (built in)" : o.gsd_file;
  if (o.json)
    print_json(device.value(), config.value(), source, std::cout);
  else {
    print_text(config.value(), source, std::cout);
    print_f_modules(device.value(), config.value(), std::cout);
  }
  return 0;
}

// `gsd check FILE`: exit 0 when the file is read (warnings or not), 2 when it is refused.
int run_check(const Options& o) {
  const auto file = read_whole_file(o.check_file);
  if (!file) {
    std::cerr << "rs4sim gsd check: cannot read " << o.check_file << ": " << file.error << "\n";
    return 2;
  }
  const auto device = gsd::parse(file.bytes, o.check_file);
  if (!device) {
    std::cerr << "rs4sim gsd check: " << device.error().what() << "\n";
    return 2;
  }
  std::cout << gsd::check_report(device.value());
  return std::cout.good() ? 0 : 1;
}

int run(const Options& o) {
  if (o.check && o.check->parsed()) {
    if (o.prm || !o.output.empty()) throw UsageError("gsd check takes no --prm or --output");
    return run_check(o);
  }
  if (!o.prm && (o.json || o.address || o.f_source_add || o.f_wd_time || o.f_check_seqnr ||
                 !o.gsd_file.empty() || !o.modules.empty() || !o.sets.empty())) {
    throw UsageError("gsd: --json, --address, --f-*, --gsd, --module and --set need --prm");
  }
  if (o.prm) return run_prm(o);
  const std::string_view text = gsd::rs4sim_gsd_text();
  if (o.output.empty()) {
    std::cout.write(text.data(), static_cast<std::streamsize>(text.size()));
    return std::cout.good() ? 0 : 1;
  }
  std::ofstream out(o.output, std::ios::binary);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out.flush()) {
    std::cerr << "rs4sim gsd: cannot write " << o.output << "\n";
    return 1;
  }
  return 0;
}

const CommandRegistration kRegistration{
    "gsd",
    "Print the virtual RS4/PROFIsafe's GSD file, or (--prm) its Set_Prm user data and Chk_Cfg",
    [](CLI::App& cmd) -> Action {
      auto o = std::make_shared<Options>();
      cmd.add_option("--output,-o", o->output, "write the GSD file here instead of stdout");
      cmd.add_flag("--prm", o->prm,
                   "print Ident_Number, Chk_Cfg and User_Prm_Data instead of the GSD");
      cmd.add_flag("--json", o->json, "with --prm: JSON output");
      cmd.add_option("--address", o->address,
                     "PROFIBUS address; the built-in GSD sets F_Dest_Add = 500 + address")
          ->check(CLI::Range(0, 126));
      cmd.add_option("--f-source-add", o->f_source_add, "F_Source_Add");
      cmd.add_option("--f-wd-time", o->f_wd_time, "F_WD_Time in ms");
      cmd.add_flag("--f-check-seqnr", o->f_check_seqnr,
                   "F_Check_SeqNr = 1 (consecutive number in CRC2)");
      cmd.add_option("--gsd", o->gsd_file, "use this GSD file instead of the built-in one");
      cmd.add_option("--module", o->modules,
                     "module name (repeat for a modular station, in slot order)");
      cmd.add_option("--set", o->sets, "NAME=VALUE: set any ExtUserPrmData parameter by name");
      o->check = cmd.add_subcommand(
          "check", "Read a GSD file as rs4sim does: ident, rates, modules, parameters, warnings");
      o->check->add_option("file", o->check_file, "the GSD file")->required();
      return [o] { return run(*o); };
    }};

}  // namespace
}  // namespace rs4sim::app
