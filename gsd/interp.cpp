// GSD interpreter: top-level keywords ([PROFIBUS GSD spec general keywords, DPV1 keywords]), then
// blocks.
#include "gsd/interp.h"

#include "gsd/f_module.h"
#include "gsd/interp_detail.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <functional>
#include <limits>
#include <set>
#include <unordered_map>

namespace rs4sim::gsd {
namespace {

using detail::error;

struct NumberKey {
  std::string_view keyword;
  std::int64_t lo;
  std::int64_t hi;
  void (*set)(Device&, std::int64_t);
};

template <class T>
T narrow(std::int64_t v) {
  return static_cast<T>(v);
}

// Every numeric keyword the interpreter uses, with the range the GSD allows.
// A value outside lo..hi is taken at the nearer limit with a warning (`Max_Input_Len = 249`:
// a Data_Exchange telegram carries 244 bytes at most, [IEC 61158-6-3 Data_Exchange]), except
// Ident_Number, without which the master has nothing to send.
const std::array<NumberKey, 42> kNumberKeys{{
    {"GSD_Revision", 0, 255, [](Device& d, std::int64_t v) { d.gsd_revision = narrow<int>(v); }},
    {"Ident_Number", 0, 0xFFFF,
     [](Device& d, std::int64_t v) { d.ident_number = narrow<std::uint16_t>(v); }},
    {"Modular_Station", 0, 1, [](Device& d, std::int64_t v) { d.modular_station = v == 1; }},
    {"Max_Module", 1, 244,
     [](Device& d, std::int64_t v) { d.max_module = narrow<std::uint8_t>(v); }},
    {"Max_Input_Len", 0, 244,
     [](Device& d, std::int64_t v) { d.max_input_len = narrow<std::uint8_t>(v); }},
    {"Max_Output_Len", 0, 244,
     [](Device& d, std::int64_t v) { d.max_output_len = narrow<std::uint8_t>(v); }},
    {"Max_Data_Len", 0, 488,
     [](Device& d, std::int64_t v) { d.max_data_len = narrow<std::uint16_t>(v); }},
    {"Max_Diag_Data_Len", 6, 244,
     [](Device& d, std::int64_t v) { d.max_diag_data_len = narrow<std::uint8_t>(v); }},
    {"Min_Slave_Intervall", 1, 0xFFFF,
     [](Device& d, std::int64_t v) { d.min_slave_interval = narrow<std::uint16_t>(v); }},
    {"Fail_Safe", 0, 1, [](Device& d, std::int64_t v) { d.fail_safe = v == 1; }},
    {"Freeze_Mode_supp", 0, 1, [](Device& d, std::int64_t v) { d.freeze_mode = v == 1; }},
    {"Sync_Mode_supp", 0, 1, [](Device& d, std::int64_t v) { d.sync_mode = v == 1; }},
    {"Auto_Baud_supp", 0, 1, [](Device& d, std::int64_t v) { d.auto_baud = v == 1; }},
    {"Set_Slave_Add_supp", 0, 1, [](Device& d, std::int64_t v) { d.set_slave_add = v == 1; }},
    {"Max_User_Prm_Data_Len", 0, 237,
     [](Device& d, std::int64_t v) { d.max_user_prm_data_len = narrow<std::uint8_t>(v); }},
    {"DPV1_Slave", 0, 1, [](Device& d, std::int64_t v) { d.dpv1.slave = v == 1; }},
    {"C1_Read_Write_supp", 0, 1, [](Device& d, std::int64_t v) { d.dpv1.c1_read_write = v == 1; }},
    {"C2_Read_Write_supp", 0, 1, [](Device& d, std::int64_t v) { d.dpv1.c2_read_write = v == 1; }},
    {"C1_Max_Data_Len", 0, 240,
     [](Device& d, std::int64_t v) { d.dpv1.c1_max_data_len = narrow<std::uint8_t>(v); }},
    {"C2_Max_Data_Len", 0, 240,
     [](Device& d, std::int64_t v) { d.dpv1.c2_max_data_len = narrow<std::uint8_t>(v); }},
    {"C1_Response_Timeout", 1, 0xFFFF,
     [](Device& d, std::int64_t v) { d.dpv1.c1_response_timeout = narrow<std::uint16_t>(v); }},
    {"C2_Response_Timeout", 1, 0xFFFF,
     [](Device& d, std::int64_t v) { d.dpv1.c2_response_timeout = narrow<std::uint16_t>(v); }},
    {"C2_Max_Count_Channels", 0, 32,
     [](Device& d, std::int64_t v) { d.dpv1.c2_max_count_channels = narrow<std::uint8_t>(v); }},
    {"Diagnostic_Alarm_supp", 0, 1,
     [](Device& d, std::int64_t v) { d.dpv1.diagnostic_alarm = v == 1; }},
    {"Process_Alarm_supp", 0, 1, [](Device& d, std::int64_t v) { d.dpv1.process_alarm = v == 1; }},
    {"Pull_Plug_Alarm_supp", 0, 1,
     [](Device& d, std::int64_t v) { d.dpv1.pull_plug_alarm = v == 1; }},
    {"Status_Alarm_supp", 0, 1, [](Device& d, std::int64_t v) { d.dpv1.status_alarm = v == 1; }},
    {"Update_Alarm_supp", 0, 1, [](Device& d, std::int64_t v) { d.dpv1.update_alarm = v == 1; }},
    {"Manufacturer_Specific_Alarm_supp", 0, 1,
     [](Device& d, std::int64_t v) { d.dpv1.manufacturer_specific_alarm = v == 1; }},
    // DPV1_Status_3 Alarm_Mode can express 1 (per type), 2, 4, 8, 12, 16, 24, 32
    // ([IEC 61158-6-3 DPV1_Status])
    {"Alarm_Sequence_Mode_Count", 0, 32,
     [](Device& d, std::int64_t v) { d.dpv1.alarm_sequence_mode_count = narrow<std::uint8_t>(v); }},
    {"Alarm_Type_Mode_supp", 0, 1,
     [](Device& d, std::int64_t v) { d.dpv1.alarm_type_mode = v == 1; }},
    {"WD_Base_1ms_supp", 0, 1, [](Device& d, std::int64_t v) { d.dpv1.wd_base_1ms = v == 1; }},
    {"Check_Cfg_Mode", 0, 1, [](Device& d, std::int64_t v) { d.dpv1.check_cfg_mode = v == 1; }},
    {"Prm_Block_Structure_supp", 0, 1,
     [](Device& d, std::int64_t v) { d.dpv1.prm_block_structure = v == 1; }},
    {"FixPresetModules", 0, 1, [](Device& d, std::int64_t v) { d.fix_preset_modules = v == 1; }},
    {"Modul_Offset", 0, 255,
     [](Device& d, std::int64_t v) { d.modul_offset = narrow<std::uint8_t>(v); }},
    {"Protocol_Ident", 0, 0, [](Device&, std::int64_t) {}},  // 0 = PROFIBUS-DP
    {"Station_Type", 0, 0, [](Device&, std::int64_t) {}},    // 0 = DP slave
    {"FMS_supp", 0, 1, [](Device&, std::int64_t) {}},
    {"Revision_Number", 0, 63, [](Device&, std::int64_t) {}},
    {"Redundancy", 0, 1, [](Device&, std::int64_t) {}},
    {"Repeater_Ctrl_Sig", 0, 2, [](Device&, std::int64_t) {}},
}};

struct StringKey {
  std::string_view keyword;
  std::string Device::*field;
};
const std::array<StringKey, 5> kStringKeys{{
    {"Vendor_Name", &Device::vendor_name},
    {"Model_Name", &Device::model_name},
    {"Revision", &Device::revision},
    {"OrderNumber", &Device::order_number},
    {"Info_Text", &Device::info_text},
}};

struct BaudName {
  std::string_view name;
  std::string_view label;
  std::uint32_t bps;
};
constexpr std::array<BaudName, 10> kBauds{{{"9.6", "9.6k", 9600},
                                           {"19.2", "19.2k", 19200},
                                           {"45.45", "45.45k", 45450},
                                           {"93.75", "93.75k", 93750},
                                           {"187.5", "187.5k", 187500},
                                           {"500", "500k", 500000},
                                           {"1.5M", "1.5M", 1500000},
                                           {"3M", "3M", 3000000},
                                           {"6M", "6M", 6000000},
                                           {"12M", "12M", 12000000}}};

std::string lower(std::string_view s) {
  std::string out(s);
  for (auto& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

class Interpreter {
 public:
  explicit Interpreter(const syntax::File& file) : file_(file) { device_.file = file.name; }
  Result<Device> run();

 private:
  Result<void> definitions();  // pass 1: PrmText, ExtUserPrmData
  Result<void> statement(const syntax::Statement& st);
  Result<std::optional<std::int64_t>> ranged(const syntax::Statement& st, std::int64_t lo,
                                             std::int64_t hi);
  Result<bool> baud_keyword(const syntax::Statement& st);
  Result<void> legacy_user_prm(const syntax::Statement& st);
  Result<void> slave_family(const syntax::Statement& st);
  Result<void> block(const syntax::Entry& e);
  Result<void> module(const syntax::Entry& e);
  Result<void> finish();
  void once(const syntax::Statement& st);
  void warn(const syntax::Statement& st, std::string message) {
    detail::warn(warnings_, file_.name, st, std::move(message));
  }

  const syntax::File& file_;
  Device device_;
  detail::TemplateBuilder global_{"global User_Prm_Data", {}, {}, {}, std::nullopt, nullptr};
  std::map<std::string, int> seen_;                    // lower-case keyword(+arg) → line
  std::set<std::string> given_;                        // keywords present (lower case)
  std::unordered_map<std::string, int> module_names_;  // lower case, trimmed → line
  std::vector<const syntax::Entry*> slot_blocks_;
  std::vector<Warning> warnings_;
};

// A keyword given twice: engineering tools take the later value, so does rs4sim, with a warning.
void Interpreter::once(const syntax::Statement& st) {
  std::string key = lower(st.keyword);
  const auto [it, fresh] = seen_.emplace(key, st.line);
  if (!fresh) {
    warn(st, st.keyword + " already given at line " + std::to_string(it->second) +
                 "; this later value taken");
    it->second = st.line;
  }
  given_.insert(std::move(key));
}

// `keyword = n`: n, clamped into lo..hi with a warning; nullopt (with a warning) when the line
// holds no number. Ident_Number is never forgiven.
Result<std::optional<std::int64_t>> Interpreter::ranged(const syntax::Statement& st,
                                                        std::int64_t lo, std::int64_t hi) {
  const bool strict = st.is("Ident_Number");
  auto v = detail::number(file_.name, st, std::numeric_limits<std::int64_t>::min(),
                          std::numeric_limits<std::int64_t>::max());
  if (!v) {
    if (strict) return std::move(v).error();
    RS4SIM_GSD_TRYV(detail::forgive(warnings_, std::move(v).error()));
    return std::optional<std::int64_t>{};
  }
  const std::int64_t value = v.value();
  if (value >= lo && value <= hi) return std::optional<std::int64_t>{value};
  const std::string what = st.keyword + " = " + std::to_string(value) + " is out of range " +
                           std::to_string(lo) + ".." + std::to_string(hi);
  if (strict) return error(file_.name, st, GsdError::kOutOfRange, what);
  const std::int64_t taken = std::clamp(value, lo, hi);
  warn(st, what + "; " + std::to_string(taken) + " taken");
  return std::optional<std::int64_t>{taken};
}

Result<void> Interpreter::definitions() {
  for (const auto& e : file_.entries) {
    if (!e.body) continue;
    if (e.statement.is("ExtUserPrmData")) {
      RS4SIM_GSD_TRY(auto p, detail::interpret_ext_param(file_.name, e));
      const int n = p.number;
      if (!device_.params.emplace(n, std::move(p)).second) {
        return error(file_.name, e.statement, GsdError::kDuplicate,
                     "ExtUserPrmData " + std::to_string(n) + " already defined at line " +
                         std::to_string(device_.params.at(n).line));
      }
    } else if (e.statement.is("PrmText")) {
      RS4SIM_GSD_TRY(auto t, detail::interpret_prm_text(file_.name, e, warnings_));
      const int n = t.number;
      if (!device_.prm_texts.emplace(n, std::move(t)).second) {
        return error(file_.name, e.statement, GsdError::kDuplicate,
                     "PrmText " + std::to_string(n) + " defined twice");
      }
    }
  }
  for (const auto& [n, p] : device_.params) {
    if (p.prm_text_ref && !device_.prm_texts.count(*p.prm_text_ref)) {
      return Error{GsdError::kUnknownReference, file_.name, p.line, p.name,
                   "Prm_Text_Ref = " + std::to_string(*p.prm_text_ref) + " names no PrmText"};
    }
  }
  return boost::outcome_v2::success();
}

Result<bool> Interpreter::baud_keyword(const syntax::Statement& st) {
  for (std::size_t i = 0; i < kBauds.size(); ++i) {
    const std::string name(kBauds[i].name);
    const bool supp = st.is(name + "_supp");
    if (!supp && !st.is("MaxTsdr_" + name)) continue;
    once(st);
    RS4SIM_GSD_TRY(const auto v, ranged(st, 0, supp ? 1 : 0xFFFF));
    if (v && supp) device_.baud_rates[i].supported = *v == 1;
    if (v && !supp) device_.baud_rates[i].max_tsdr = static_cast<std::uint16_t>(*v);
    return true;
  }
  return false;
}

Result<void> Interpreter::legacy_user_prm(const syntax::Statement& st) {
  once(st);
  if (!st.has_equals || st.fields.size() != 1) {
    return error(file_.name, st, GsdError::kBadValue, "User_Prm_Data expects bytes b0,b1,…");
  }
  RS4SIM_GSD_TRY(auto bytes, detail::byte_list(file_.name, st, st.fields[0]));
  global_.consts.push_back({0, std::move(bytes), &st});
  return boost::outcome_v2::success();
}

// `Slave_Family = 3` or `Slave_Family = 9@AS-I@…` ([PROFIBUS GSD spec Slave_Family]).
Result<void> Interpreter::slave_family(const syntax::Statement& st) {
  once(st);
  const auto bad = [&] {
    return error(file_.name, st, GsdError::kBadValue,
                 "Slave_Family expects a family number, optionally followed by @sub-families");
  };
  if (!st.has_equals || st.fields.size() != 1 || st.fields[0].size() != 1) return bad();
  const auto& v = st.fields[0][0];
  std::int64_t main = 0;
  if (v.is_number()) {
    main = v.number;
  } else if (v.kind == syntax::Value::Kind::kName) {
    const std::string& t = v.text;
    const auto at = t.find('@');
    if (at == 0 || at == std::string::npos || at > 3) return bad();
    for (std::size_t i = 0; i < at; ++i) {
      if (std::isdigit(static_cast<unsigned char>(t[i])) == 0) return bad();
      main = main * 10 + (t[i] - '0');
    }
    for (std::size_t pos = at + 1; pos <= t.size();) {
      const auto next = std::min(t.find('@', pos), t.size());
      const std::string_view sub = trim_blanks(std::string_view(t).substr(pos, next - pos));
      if (sub.empty()) return bad();  // "3@" or "3@@x"
      device_.sub_families.emplace_back(sub);
      pos = next + 1;
    }
  } else {
    return bad();
  }
  if (main < 0 || main > 255) {
    return error(file_.name, st, GsdError::kOutOfRange,
                 "Slave_Family = " + std::to_string(main) + " is out of range 0..255");
  }
  device_.slave_family = static_cast<std::uint8_t>(main);
  return boost::outcome_v2::success();
}

Result<void> Interpreter::statement(const syntax::Statement& st) {
  for (const auto& key : kNumberKeys) {
    if (!st.is(key.keyword)) continue;
    once(st);
    RS4SIM_GSD_TRY(const auto v, ranged(st, key.lo, key.hi));
    if (v) key.set(device_, *v);
    return boost::outcome_v2::success();
  }
  for (const auto& key : kStringKeys) {
    if (!st.is(key.keyword)) continue;
    once(st);
    auto text = detail::string_value(file_.name, st);
    if (!text) return detail::forgive(warnings_, std::move(text).error());
    device_.*key.field = std::move(text).value();
    return boost::outcome_v2::success();
  }
  RS4SIM_GSD_TRY(const bool baud, baud_keyword(st));
  if (baud) return boost::outcome_v2::success();
  if (st.is("Ext_User_Prm_Data_Const")) return global_.add_const(file_.name, st);
  if (st.is("Ext_User_Prm_Data_Ref")) return global_.add_ref(file_.name, st);
  if (st.is("User_Prm_Data")) return legacy_user_prm(st);
  if (st.is("Slave_Family")) return detail::forgive(warnings_, slave_family(st));
  if (st.is("Unit_Diag_Bit") || st.is("Unit_Diag_Not_Bit")) {
    return detail::forgive(warnings_,
                           detail::interpret_unit_diag_bit(file_.name, st, device_.unit_diag));
  }
  if (st.is("Channel_Diag")) {
    return detail::forgive(warnings_,
                           detail::interpret_channel_diag(file_.name, st, device_.unit_diag));
  }
  if (st.is("User_Prm_Data_Len")) {
    once(st);
    RS4SIM_GSD_TRY(const auto len, ranged(st, 0, 237));
    if (len) global_.length = static_cast<std::size_t>(*len);
    if (len) global_.length_st = &st;
  }
  return boost::outcome_v2::success();  // a keyword a master does not need
}

Result<void> Interpreter::finish() {
  if (!given_.count("ident_number")) {
    return Error{GsdError::kMissingKeyword, file_.name, 0, "", "Ident_Number is missing"};
  }
  bool any = false;
  for (const auto& b : device_.baud_rates) {
    if (b.supported && !b.max_tsdr) {
      warnings_.push_back({file_.name, seen_.at(lower(std::string(b.name) + "_supp")),
                           std::string(b.name) + "_supp = 1",
                           "MaxTsdr_" + std::string(b.name) +
                               " is missing; the master keeps its own slot time at this rate"});
    }
    any = any || b.supported;
  }
  if (!any)
    return Error{GsdError::kMissingKeyword, file_.name, 0, "",
                 "no baud rate is supported (<rate>_supp = 1)"};
  std::optional<std::size_t> max;
  if (device_.max_user_prm_data_len) max = *device_.max_user_prm_data_len;
  RS4SIM_GSD_TRY(device_.user_prm, global_.finish(file_.name, device_.params, max));
  if (device_.dpv1.slave && device_.user_prm.length < 3) {
    return Error{GsdError::kMissingKeyword, file_.name, 0, "",
                 "DPV1_Slave = 1 but User_Prm_Data does not hold the 3 DPV1_Status bytes"};
  }
  return boost::outcome_v2::success();
}

// A module named as an earlier one (blanks and case aside): listed, but --module finds the first.
Result<void> Interpreter::module(const syntax::Entry& e) {
  RS4SIM_GSD_TRY(auto m, detail::interpret_module(file_.name, e, device_.params));
  const auto [first, fresh] = module_names_.emplace(lower(trim_blanks(m.name)), m.line);
  if (!fresh) {
    warn(e.statement, "module \"" + m.name + "\" already defined at line " +
                          std::to_string(first->second) +
                          "; a --module of this name takes the first");
  }
  device_.modules.push_back(std::move(m));
  return boost::outcome_v2::success();
}

Result<void> Interpreter::block(const syntax::Entry& e) {
  if (e.statement.is("Module")) return module(e);
  if (e.statement.is("SlotDefinition")) slot_blocks_.push_back(&e);
  if (e.statement.is("Unit_Diag_Area")) {
    return detail::forgive(warnings_,
                           detail::interpret_unit_diag_area(file_.name, e, device_.unit_diag));
  }
  if (e.statement.is("UnitDiagType")) {
    return detail::forgive(warnings_, detail::interpret_unit_diag_type(file_.name, e,
                                                                       device_.unit_diag, warnings_));
  }
  return boost::outcome_v2::success();
}

Result<Device> Interpreter::run() {
  for (const auto& b : kBauds) {
    device_.baud_rates.push_back({b.name, b.label, b.bps, false, std::nullopt});
  }
  RS4SIM_GSD_TRYV(definitions());
  device_.modules.reserve(file_.entries.size());
  for (const auto& e : file_.entries) {
    if (!e.body) {
      RS4SIM_GSD_TRYV(statement(e.statement));
    } else {
      RS4SIM_GSD_TRYV(block(e));
    }
  }
  for (const syntax::Entry* e : slot_blocks_) {
    RS4SIM_GSD_TRY(auto slots, detail::interpret_slots(file_.name, *e, device_.modules, warnings_));
    device_.slots.insert(device_.slots.end(), slots.begin(), slots.end());
  }
  RS4SIM_GSD_TRYV(finish());
  RS4SIM_GSD_TRYV(check_f_modules(device_));
  device_.warnings = file_.warnings;
  device_.warnings.insert(device_.warnings.end(), warnings_.begin(), warnings_.end());
  std::stable_sort(device_.warnings.begin(), device_.warnings.end(),
                   [](const Warning& a, const Warning& b) { return a.line < b.line; });
  device_.latin1 = file_.latin1;
  return std::move(device_);
}

}  // namespace

Result<Device> interpret(const syntax::File& file) { return Interpreter(file).run(); }

Result<Device> parse(std::string_view text, std::string file_name) {
  RS4SIM_GSD_TRY(auto file, syntax::parse_syntax(text, std::move(file_name)));
  return interpret(file);
}

}  // namespace rs4sim::gsd
