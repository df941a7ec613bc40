#include "gsd/check_report.h"

#include "gsd/config.h"
#include "gsd/f_module.h"

#include <cstdio>
#include <sstream>

namespace rs4sim::gsd {
namespace {

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

void station(const Device& d, std::ostream& out) {
  out << "GSD: " << d.file << " (GSD_Revision " << d.gsd_revision
      << (d.latin1 ? ", ISO 8859-1 text converted to UTF-8" : "") << ")\n";
  out << "Vendor_Name: " << d.vendor_name << "\nModel_Name: " << d.model_name << "\n";
  out << "Ident_Number: " << hex16(d.ident_number) << "\n";
  out << "Station: " << (d.modular_station ? "modular" : "compact");
  if (d.modular_station) out << ", Max_Module " << unsigned{d.max_module};
  out << ", Modul_Offset " << unsigned{d.modul_offset}
      << (d.fix_preset_modules ? ", FixPresetModules" : "") << ", "
      << (d.dpv1.slave ? "DP-V1" : "DP-V0") << "\n";
  out << "Max_Input_Len " << unsigned{d.max_input_len} << ", Max_Output_Len "
      << unsigned{d.max_output_len} << ", Max_Data_Len " << d.max_data_len << ", Max_Diag_Data_Len "
      << unsigned{d.max_diag_data_len} << "\n";
  out << "Rates (MaxTsdr, bit times):";
  for (const auto& b : d.baud_rates) {
    if (!b.supported) continue;
    out << " " << b.label << " " << (b.max_tsdr ? std::to_string(*b.max_tsdr) : "?");
  }
  out << "\n";
}

void modules(const Device& d, std::ostream& out) {
  out << "Modules (" << d.modules.size() << "):\n";
  for (const auto& m : d.modules) {
    out << "  " << quoted(m.name) << "  Cfg " << hex_bytes(m.cfg) << "  in " << m.input_len
        << " out " << m.output_len;
    if (m.reference) out << "  ref " << *m.reference;
    if (m.prm.length) out << "  prm " << m.prm.length << " bytes";
    if (m.f_prm) out << "  F-parameters";
    out << (m.preset ? "  preset" : "") << "  (line " << m.line << ")\n";
  }
  if (d.slots.empty()) return;
  out << "Slots (SlotDefinition):\n";
  for (const auto& s : d.slots) {
    std::string allowed;
    for (const auto r : s.allowed) {
      const Module* m = d.find_module_by_reference(r);
      allowed += (allowed.empty() ? "" : ", ") + (m ? quoted(m->name) : std::to_string(r));
    }
    const Module* def = d.find_module_by_reference(s.default_ref);
    out << "  Slot(" << s.number << ") " << quoted(s.name) << ": default "
        << (def ? quoted(def->name) : std::to_string(s.default_ref)) << ", allows " << allowed
        << "\n";
  }
}

void default_configuration(const Device& d, std::ostream& out) {
  auto c = configure(d, {});
  if (!c) {
    out << "Default configuration: none without --module (" << c.error().message << ")\n";
    return;
  }
  const SlaveSetup& s = c.value();
  out << "Default configuration:";
  for (std::size_t i = 0; i < s.slots.size(); ++i) {
    out << (i ? ", " : " ") << "slot " << s.slots[i].slot << " " << quoted(s.modules[i])
        << (s.slots[i].preset ? " (preset)" : "");
  }
  out << "\n  Chk_Cfg: " << hex_bytes(s.cfg) << "\n  Input_Len " << s.input_len << ", Output_Len "
      << s.output_len
      << "\n  User_Prm_Data: " << (s.user_prm_data.empty() ? "(none)" : hex_bytes(s.user_prm_data))
      << "\n";
}

// `n "name" Type(bits), default v, range a..b[, fixed][, texts …]`
void parameter(const Device& d, int n, const ExtParam& p, std::ostream& out) {
  out << n << " " << quoted(p.name) << " " << to_string(p.type);
  if (p.type == ParamType::kBit) out << "(" << p.bit_low << ")";
  if (p.type == ParamType::kBitArea) out << "(" << p.bit_low << "-" << p.bit_high << ")";
  out << ", default " << p.default_value << ", " << (p.allowed.empty() ? "range " : "values ")
      << p.range_text() << (p.changeable ? "" : ", fixed");
  const auto texts = p.prm_text_ref ? d.prm_texts.find(*p.prm_text_ref) : d.prm_texts.end();
  if (texts != d.prm_texts.end()) {
    std::string list;
    for (const auto& [v, t] : texts->second.texts) {
      list += (list.empty() ? "" : ", ") + std::to_string(v) + " " + quoted(t);
    }
    out << ", texts " << list;
  }
  out << "\n";
}

void parameters(const Device& d, std::ostream& out) {
  if (d.params.empty()) return;
  out << "Parameters (" << d.params.size() << "):\n";
  for (const auto& [n, p] : d.params) {
    out << "  ";
    parameter(d, n, p, out);
  }
}

std::string optional_crc(const std::optional<std::uint16_t>& crc) {
  return crc ? std::to_string(*crc) + " (" + hex16(*crc) + ")" : std::string("not given");
}

void f_module(const Device& d, const Module& m, std::ostream& out) {
  auto f = describe_f_module(d, m);
  out << "F-module " << quoted(m.name) << " (line " << m.line << "): ";
  if (!f) {
    out << f.error().message << "\n";
    return;
  }
  const FModuleInfo& info = f.value();
  const FParameterDefaults& def = info.defaults;
  out << to_text(info.io) << "\n  F-parameters of " << quoted(m.name) << ": "
      << hex_bytes(def.block) << "; F_Par_CRC in the file " << hex16(def.file_crc)
      << ", CRC1 over the defaults " << hex16(def.crc1)
      << (def.file_crc == def.crc1 ? " (equal)" : " (differs)") << "\n  at byte " << def.offset
      << " of the F-part (F_Ext_Module_Prm_Data_Len " << m.f_prm->length << "):\n";
  for (const auto& field : info.fields) {
    out << "    +" << field.offset << " ";
    parameter(d, field.param->number, *field.param, out);
  }
  out << "  F_ParamDescCRC " << optional_crc(m.f_param_desc_crc) << ", F_IO_StructureDescCRC "
      << optional_crc(m.f_io_structure_desc_crc) << "\n";
}

void f_modules(const Device& d, std::ostream& out) {
  for (const auto& m : d.modules) {
    if (is_f_module(m)) f_module(d, m, out);
  }
}

}  // namespace

std::string hex_bytes(const std::vector<std::uint8_t>& bytes) {
  std::string out;
  char b[4];
  for (const auto v : bytes) {
    std::snprintf(b, sizeof b, "%02X", v);
    out += (out.empty() ? "" : " ") + std::string(b);
  }
  return out;
}

std::string hex16(unsigned v) {
  char b[8];
  std::snprintf(b, sizeof b, "0x%04X", v & 0xFFFFU);
  return b;
}

std::string check_report(const Device& device) {
  std::ostringstream out;
  station(device, out);
  modules(device, out);
  default_configuration(device, out);
  parameters(device, out);
  f_modules(device, out);
  out << "Warnings (" << device.warnings.size() << ")" << (device.warnings.empty() ? "" : ":")
      << "\n";
  for (const auto& w : device.warnings) out << "  " << w.what() << "\n";
  return out.str();
}

}  // namespace rs4sim::gsd
