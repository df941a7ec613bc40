// Slave configuration from a GSD: Set_Prm user data and Chk_Cfg
// ([PROFIBUS GSD spec User_Prm_Data]).
#include "gsd/config.h"

#include "codec/endian.h"
#include "codec/writer.h"
#include "gsd/syntax.h"
#include "profisafe/crc.h"

#include <algorithm>
#include <set>

namespace rs4sim::gsd {
namespace {

Error config_error(GsdError code, std::string message) {
  return Error{code, "", 0, "", std::move(message)};
}

// Writes `value` at `at` as the parameter type says: bits in place, integers big-endian.
void write_value(std::vector<std::uint8_t>& data, std::size_t at, const ExtParam& p,
                 std::int64_t value) {
  if (p.type == ParamType::kBit || p.type == ParamType::kBitArea) {
    const unsigned width = static_cast<unsigned>(p.bit_high - p.bit_low + 1);
    const unsigned mask = ((1U << width) - 1U) << p.bit_low;
    const unsigned bits = (static_cast<unsigned>(value) << p.bit_low) & mask;
    data[at] = static_cast<std::uint8_t>((data[at] & ~mask) | bits);
    return;
  }
  const std::size_t n = byte_size(p.type);
  const auto raw = static_cast<std::uint32_t>(value);  // two's complement for Signed*
  for (std::size_t i = 0; i < n; ++i) {
    data[at + i] = static_cast<std::uint8_t>(raw >> (8 * (n - 1 - i)));
  }
}

// The inverse of write_value.
std::int64_t read_value(std::span<const std::uint8_t> data, std::size_t at, const ExtParam& p) {
  if (p.type == ParamType::kBit || p.type == ParamType::kBitArea) {
    const unsigned width = static_cast<unsigned>(p.bit_high - p.bit_low + 1);
    return (data[at] >> p.bit_low) & ((1U << width) - 1U);
  }
  const std::size_t n = byte_size(p.type);
  std::uint32_t raw = 0;
  for (std::size_t i = 0; i < n; ++i) raw = (raw << 8) | data[at + i];
  switch (p.type) {
    case ParamType::kSigned8: return static_cast<std::int8_t>(raw);
    case ParamType::kSigned16: return static_cast<std::int16_t>(raw);
    case ParamType::kSigned32: return static_cast<std::int32_t>(raw);
    default: return raw;
  }
}

// Where the F_Par_CRC reference of a module's F-part lies (offset in the F template).
Result<std::size_t> f_par_crc_offset(const Device& d, const Module& m) {
  const auto crc_ref = std::find_if(
      m.f_prm->refs.begin(), m.f_prm->refs.end(),
      [&](const PrmRef& r) { return syntax::iequals(d.params.at(r.param).name, "F_Par_CRC"); });
  if (crc_ref == m.f_prm->refs.end() || crc_ref->offset < 8 ||
      byte_size(d.params.at(crc_ref->param).type) != 2) {
    return config_error(
        GsdError::kFParameterLayout,
        "module \"" + m.name +
            "\": the F-parameters need a 2-byte F_Par_CRC reference at offset 8 or later");
  }
  return crc_ref->offset;
}

Result<profisafe::FParameters> read_f_block(const Module& m, const std::vector<std::uint8_t>& data,
                                            std::size_t start) {
  const std::span<const std::uint8_t> block(data.data() + start, profisafe::kFParametersSize);
  auto parsed = profisafe::parse_f_parameters(block);
  if (!parsed) {
    return config_error(
        GsdError::kFParameterLayout,
        "module \"" + m.name + "\": F-parameter block: " + parsed.error().message());
  }
  return parsed.value();
}

// "\"A\", \"B\"" for messages: the modules a user may name (not the presets), at most 40.
std::string choosable(const Device& d) {
  std::string out;
  std::size_t n = 0;
  for (const auto& m : d.modules) {
    if (m.preset) continue;
    if (++n <= 40) out += (out.empty() ? "\"" : ", \"") + m.name + "\"";
  }
  if (n > 40) out += ", … (" + std::to_string(n) + " in all)";
  return out.empty() ? std::string("none") : out;
}

std::size_t index_of(const Device& d, const Module* m) {
  return static_cast<std::size_t>(m - d.modules.data());
}

class Placement {
 public:
  explicit Placement(const Device& d) : d_(d) {
    for (const auto& m : d_.modules) {
      if (m.preset) add(index_of(d_, &m), true, false);
    }
    for (const auto& s : d_.slots) {
      if (s.number >= d_.modul_offset + static_cast<int>(out_.size())) free_.push_back(&s);
    }
  }
  Result<void> user(const std::string& name);
  void defaults();
  Result<std::vector<PlacedModule>> finish(bool user_given);

 private:
  void add(std::size_t index, bool preset, bool slot_default) {
    out_.push_back({index, d_.modul_offset + static_cast<int>(out_.size()), preset, slot_default});
  }
  const Device& d_;
  std::vector<PlacedModule> out_;
  std::vector<const SlotDef*> free_;  // defined slots after the presets
  std::size_t users_ = 0;
};

Result<void> Placement::user(const std::string& name) {
  const Module* m = d_.find_module(name);
  if (!m) {
    return config_error(GsdError::kUnknownModule,
                        "no module \"" + name + "\" in the GSD (modules: " + choosable(d_) + ")");
  }
  if (m->preset) {
    return config_error(GsdError::kUnknownModule,
                        "\"" + m->name + "\" is a preset module (Preset = 1), placed ahead of " +
                            "the user's modules already: --module names the modules after the " +
                            "presets (modules: " + choosable(d_) + ")");
  }
  if (users_ < free_.size()) {
    const SlotDef& s = *free_[users_];
    if (!m->reference || !std::binary_search(s.allowed.begin(), s.allowed.end(), *m->reference)) {
      std::string allowed;
      for (const auto r : s.allowed) {
        const Module* a = d_.find_module_by_reference(r);
        allowed += (allowed.empty() ? "\"" : ", \"") + (a ? a->name : std::to_string(r)) + "\"";
      }
      return config_error(GsdError::kOutOfRange, "slot " + std::to_string(s.number) + " (\"" +
                                                     s.name + "\") takes " + allowed + ", not \"" +
                                                     m->name + "\" (SlotDefinition)");
    }
  }
  ++users_;
  add(index_of(d_, m), false, false);
  return boost::outcome_v2::success();
}

// The defined slots the user left empty keep their default modules.
void Placement::defaults() {
  for (std::size_t i = users_; i < free_.size(); ++i) {
    const Module* m = d_.find_module_by_reference(free_[i]->default_ref);
    if (m) add(index_of(d_, m), false, true);
  }
}

Result<std::vector<PlacedModule>> Placement::finish(bool user_given) {
  const std::size_t selectable = static_cast<std::size_t>(std::count_if(
      d_.modules.begin(), d_.modules.end(), [](const Module& m) { return !m.preset; }));
  if (out_.empty() && !user_given && selectable == 1) {
    const auto it = std::find_if(d_.modules.begin(), d_.modules.end(),
                                 [](const Module& m) { return !m.preset; });
    add(index_of(d_, &*it), false, false);
  }
  if (out_.empty()) {
    return config_error(GsdError::kModuleCount,
                        "choose the module(s) to configure (modules: " + choosable(d_) + ")");
  }
  if (!d_.modular_station && out_.size() != 1) {
    return config_error(GsdError::kModuleCount,
                        "a compact station (Modular_Station = 0) takes exactly one module, got " +
                            std::to_string(out_.size()));
  }
  if (d_.modular_station && out_.size() > d_.max_module) {
    return config_error(GsdError::kModuleCount,
                        "a modular station takes 1.." + std::to_string(d_.max_module) +
                            " modules (Max_Module), got " + std::to_string(out_.size()));
  }
  return std::move(out_);
}

class Configurator {
 public:
  Configurator(const Device& device, const ConfigRequest& request)
      : device_(device), request_(request) {}
  Result<SlaveSetup> run();

 private:
  Result<std::int64_t> value_for(const ExtParam& p);
  Result<void> place(const PrmTemplate& t, std::size_t module, bool f_part);
  Result<void> seal_f_block(const Module& m, std::size_t module, std::size_t base);
  Result<void> check_overrides_used() const;

  const Device& device_;
  const ConfigRequest& request_;
  SlaveSetup out_;
  std::set<std::size_t> used_;  // indices into request_.overrides
};

Result<std::int64_t> Configurator::value_for(const ExtParam& p) {
  std::optional<std::int64_t> value;
  for (std::size_t i = 0; i < request_.overrides.size(); ++i) {
    if (!syntax::iequals(request_.overrides[i].name, p.name)) continue;
    used_.insert(i);
    value = request_.overrides[i].value;
  }
  if (!value) return p.default_value;
  if (syntax::iequals(p.name, "F_Par_CRC")) {
    return config_error(GsdError::kNotChangeable,
                        "F_Par_CRC is computed (CRC1 over the F-parameters) and cannot be set");
  }
  if (!p.changeable && *value != p.default_value) {
    return config_error(GsdError::kNotChangeable,
                        p.name + " is fixed at " + std::to_string(p.default_value) +
                            " (Changeable = 0), cannot set " + std::to_string(*value));
  }
  if (!p.accepts(*value)) {
    return config_error(GsdError::kOutOfRange, p.name + " = " + std::to_string(*value) +
                                                   " is out of range " + p.range_text());
  }
  return *value;
}

Result<void> Configurator::place(const PrmTemplate& t, std::size_t module, bool f_part) {
  const std::size_t base = out_.user_prm_data.size();
  out_.user_prm_data.insert(out_.user_prm_data.end(), t.defaults.begin(), t.defaults.end());
  for (const auto& ref : t.refs) {
    const ExtParam& p = device_.params.at(ref.param);  // resolved by the interpreter
    RS4SIM_GSD_TRY(const auto value, value_for(p));
    write_value(out_.user_prm_data, base + ref.offset, p, value);
    out_.fields.push_back({base + ref.offset, p.name, p.type, p.bit_low, p.bit_high, value, module,
                           f_part, ref.param});
  }
  return boost::outcome_v2::success();
}

// The 10-byte F-parameter block ends with F_Par_CRC ([IEC 61784-3-3 F-Parameters]): its 8 bytes
// before F_Par_CRC go through CRC1, the result replaces the GSD's default.
Result<void> Configurator::seal_f_block(const Module& m, std::size_t module, std::size_t base) {
  RS4SIM_GSD_TRY(const std::size_t crc_offset, f_par_crc_offset(device_, m));
  const std::size_t start = base + crc_offset - 8;
  RS4SIM_GSD_TRY(profisafe::FParameters params, read_f_block(m, out_.user_prm_data, start));
  const auto encoded = profisafe::encode_f_parameters(params);
  std::copy(encoded.begin() + 8, encoded.end(),
            out_.user_prm_data.begin() + static_cast<std::ptrdiff_t>(start + 8));
  params.par_crc = codec::be16(encoded[8], encoded[9]);
  for (auto& f : out_.fields) {
    if (f.offset == start + 8 && f.f_parameter && f.module == module) f.value = params.par_crc;
  }
  out_.f_parameters.push_back({module, start, params});
  return boost::outcome_v2::success();
}

Result<void> Configurator::check_overrides_used() const {
  for (std::size_t i = 0; i < request_.overrides.size(); ++i) {
    if (used_.count(i)) continue;
    std::set<std::string> names;
    for (const auto& f : out_.fields) names.insert(f.name);
    std::string known;
    for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
    return config_error(GsdError::kUnknownParameter,
                        "no parameter \"" + request_.overrides[i].name +
                            "\" in this configuration (parameters: " + known + ")");
  }
  return boost::outcome_v2::success();
}

Result<SlaveSetup> Configurator::run() {
  RS4SIM_GSD_TRY(out_.slots, place_modules(device_, request_.modules));
  out_.ident_number = device_.ident_number;
  out_.dpv1 = device_.dpv1.slave;
  RS4SIM_GSD_TRYV(place(device_.user_prm, kGlobal, false));
  for (std::size_t i = 0; i < out_.slots.size(); ++i) {
    const Module& m = device_.modules[out_.slots[i].index];
    out_.modules.push_back(m.name);
    out_.cfg.insert(out_.cfg.end(), m.cfg.begin(), m.cfg.end());
    out_.input_len += m.input_len;
    out_.output_len += m.output_len;
    RS4SIM_GSD_TRYV(place(m.prm, i, false));
    if (m.f_prm) {
      const std::size_t base = out_.user_prm_data.size();
      RS4SIM_GSD_TRYV(place(*m.f_prm, i, true));
      RS4SIM_GSD_TRYV(seal_f_block(m, i, base));
    }
  }
  RS4SIM_GSD_TRYV(check_overrides_used());
  // Set_Prm DU ≤ 244 bytes = 7 standard bytes + user data ([IEC 61158-6-3 Set_Prm]).
  const std::size_t limit = std::min<std::size_t>(237, device_.max_user_prm_data_len.value_or(237));
  if (out_.user_prm_data.size() > limit) {
    return config_error(GsdError::kPrmTooLong, "User_Prm_Data is " +
                                                   std::to_string(out_.user_prm_data.size()) +
                                                   " bytes, more than " + std::to_string(limit));
  }
  if (out_.dpv1) std::copy_n(out_.user_prm_data.begin(), 3, out_.dpv1_status.begin());
  return std::move(out_);
}

}  // namespace

Result<std::vector<PlacedModule>> place_modules(const Device& device,
                                                const std::vector<std::string>& user_modules) {
  Placement p(device);
  for (const auto& name : user_modules) RS4SIM_GSD_TRYV(p.user(name));
  p.defaults();
  return p.finish(!user_modules.empty());
}

Result<SlaveSetup> configure(const Device& device, const ConfigRequest& request) {
  return Configurator(device, request).run();
}

Result<void> check_user_prm(const Device& device, const SlaveSetup& setup,
                            std::span<const std::uint8_t> user_prm_data) {
  if (user_prm_data.size() != setup.user_prm_data.size()) {
    return config_error(GsdError::kPrmTooLong, "User_Prm_Data is " +
                                                   std::to_string(user_prm_data.size()) +
                                                   " bytes, the GSD configuration has " +
                                                   std::to_string(setup.user_prm_data.size()));
  }
  for (const auto& f : setup.fields) {
    if (f.f_parameter) continue;
    const auto it = device.params.find(f.param);
    if (it == device.params.end()) continue;  // a SlaveSetup of another Device
    const ExtParam& p = it->second;
    const std::int64_t v = read_value(user_prm_data, f.offset, p);
    if (!p.accepts(v)) {
      return config_error(GsdError::kOutOfRange, "byte " + std::to_string(f.offset) + ": " +
                                                     p.name + " = " + std::to_string(v) +
                                                     " is not allowed (" + p.range_text() + ")");
    }
  }
  return boost::outcome_v2::success();
}

Result<FParameterDefaults> f_parameter_defaults(const Device& device, const Module& module) {
  if (!module.f_prm) {
    return config_error(GsdError::kFParameterLayout,
                        "module \"" + module.name + "\" has no F-parameters");
  }
  std::vector<std::uint8_t> data(module.f_prm->defaults);
  for (const auto& ref : module.f_prm->refs) {
    const ExtParam& p = device.params.at(ref.param);
    write_value(data, ref.offset, p, p.default_value);
  }
  RS4SIM_GSD_TRY(const std::size_t crc_offset, f_par_crc_offset(device, module));
  const std::size_t start = crc_offset - 8;
  RS4SIM_GSD_TRY(const profisafe::FParameters params, read_f_block(module, data, start));
  const auto encoded = profisafe::encode_f_parameters(params);
  FParameterDefaults out;
  out.block.assign(data.begin() + static_cast<std::ptrdiff_t>(start),
                   data.begin() + static_cast<std::ptrdiff_t>(start + 10));
  out.offset = start;
  out.file_crc = codec::be16(data[crc_offset], data[crc_offset + 1]);
  out.crc1 = codec::be16(encoded[8], encoded[9]);
  return out;
}

std::uint16_t f_param_desc_crc(const Device& device, const Module& module) {
  if (!module.f_prm) return 0;
  std::vector<std::uint8_t> canon(module.f_prm->defaults);
  for (const auto& ref : module.f_prm->refs) {
    const ExtParam& p = device.params.at(ref.param);
    canon.push_back(static_cast<std::uint8_t>(ref.offset));
    canon.insert(canon.end(), p.name.begin(), p.name.end());
    canon.push_back(0);
    canon.push_back(static_cast<std::uint8_t>(p.type));
    canon.push_back(static_cast<std::uint8_t>(p.bit_low));
    canon.push_back(static_cast<std::uint8_t>(p.bit_high));
    codec::Appender w(canon);
    for (const std::int64_t v : {p.default_value, p.min, p.max})
      w.u32_be(static_cast<std::uint32_t>(v));
    canon.push_back(p.changeable ? 1 : 0);
  }
  return static_cast<std::uint16_t>(profisafe::crc16().update(0, canon));
}

}  // namespace rs4sim::gsd
