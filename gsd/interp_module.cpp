// Module … EndModule blocks ([PROFIBUS GSD spec modules]) with their PROFIsafe F-entries
// ([PROFIBUS GSD spec F-parameter keywords]).
#include "gsd/cfg.h"
#include "gsd/interp_detail.h"

namespace rs4sim::gsd::detail {
namespace {

struct ModuleBuilder {
  Module module;
  TemplateBuilder prm;
  TemplateBuilder f_prm;
};

Result<void> read_head(const std::string& file, const syntax::Statement& head, Module& m) {
  if (!head.has_equals || head.fields.size() != 2 || head.fields[0].size() != 1 ||
      !head.fields[0][0].is_string()) {
    return error(file, head, GsdError::kBadValue, "Module expects = \"name\" cfg,cfg,…");
  }
  m.name = head.fields[0][0].text;
  m.line = head.line;
  RS4SIM_GSD_TRY(m.cfg, byte_list(file, head, head.fields[1]));
  auto layout = decode_cfg(m.cfg);
  if (!layout) {
    return error(file, head, GsdError::kBadCfg,
                 "module \"" + m.name + "\": " + layout.error().message);
  }
  m.input_len = layout.value().input_bytes;
  m.output_len = layout.value().output_bytes;
  return boost::outcome_v2::success();
}

Result<void> read_length(const std::string& file, const syntax::Statement& st, TemplateBuilder& t) {
  if (t.length_st) {
    return error(file, st, GsdError::kDuplicate,
                 st.keyword + " already given at line " + std::to_string(t.length_st->line));
  }
  RS4SIM_GSD_TRY(const auto len, number(file, st, 0, 237));
  t.length = static_cast<std::size_t>(len);
  t.length_st = &st;
  return boost::outcome_v2::success();
}

Result<void> read_crc(const std::string& file, const syntax::Statement& st,
                      std::optional<std::uint16_t>& crc) {
  RS4SIM_GSD_TRY(const auto v, number(file, st, 0, 0xFFFF));
  crc = static_cast<std::uint16_t>(v);
  return boost::outcome_v2::success();
}

Result<void> read_body_line(const std::string& file, const syntax::Statement& st,
                            ModuleBuilder& b) {
  if (st.keyword.empty()) {  // the module's reference number
    if (b.module.reference || st.fields.size() != 1 || st.fields[0].size() != 1 ||
        !st.fields[0][0].is_number() || st.fields[0][0].number < 0) {
      return error(file, st, GsdError::kBadValue, "a module takes one reference number line");
    }
    b.module.reference = static_cast<std::uint32_t>(st.fields[0][0].number);
    return boost::outcome_v2::success();
  }
  if (st.is("Info_Text")) {
    RS4SIM_GSD_TRY(b.module.info_text, string_value(file, st));
  } else if (st.is("Ext_Module_Prm_Data_Len")) {
    RS4SIM_GSD_TRYV(read_length(file, st, b.prm));
  } else if (st.is("Ext_User_Prm_Data_Const")) {
    RS4SIM_GSD_TRYV(b.prm.add_const(file, st));
  } else if (st.is("Ext_User_Prm_Data_Ref")) {
    RS4SIM_GSD_TRYV(b.prm.add_ref(file, st));
  } else if (st.is("F_Ext_Module_Prm_Data_Len")) {
    RS4SIM_GSD_TRYV(read_length(file, st, b.f_prm));
  } else if (st.is("F_Ext_User_Prm_Data_Const")) {
    RS4SIM_GSD_TRYV(b.f_prm.add_const(file, st));
  } else if (st.is("F_Ext_User_Prm_Data_Ref")) {
    RS4SIM_GSD_TRYV(b.f_prm.add_ref(file, st));
  } else if (st.is("F_ParamDescCRC")) {
    RS4SIM_GSD_TRYV(read_crc(file, st, b.module.f_param_desc_crc));
  } else if (st.is("Preset")) {
    RS4SIM_GSD_TRY(const auto v, number(file, st, 0, 1));
    b.module.preset = v == 1;
  } else if (st.is("F_IO_StructureDescCRC")) {
    RS4SIM_GSD_TRYV(read_crc(file, st, b.module.f_io_structure_desc_crc));
  }  // Data_Area_Beg, Channel_Diag, … carry nothing the configuration needs
  return boost::outcome_v2::success();
}

// A template with bytes needs its declared length ([PROFIBUS GSD spec modules]:
// Ext_Module_Prm_Data_Len).
Result<void> require_length(const std::string& file, const syntax::Statement& head,
                            const TemplateBuilder& t, std::string_view keyword) {
  if (!t.empty() && !t.length) {
    return error(file, head, GsdError::kMissingKeyword,
                 t.what + " has parameter bytes but no " + std::string(keyword));
  }
  return boost::outcome_v2::success();
}

}  // namespace

Result<Module> interpret_module(const std::string& file, const syntax::Entry& entry,
                                const std::map<int, ExtParam>& params) {
  ModuleBuilder b;
  RS4SIM_GSD_TRYV(read_head(file, entry.statement, b.module));
  b.prm.what = "module \"" + b.module.name + "\"";
  b.f_prm.what = "module \"" + b.module.name + "\" F-parameters";
  for (const auto& st : *entry.body) {
    RS4SIM_GSD_TRYV(read_body_line(file, st, b));
  }
  RS4SIM_GSD_TRYV(require_length(file, entry.statement, b.prm, "Ext_Module_Prm_Data_Len"));
  RS4SIM_GSD_TRYV(require_length(file, entry.statement, b.f_prm, "F_Ext_Module_Prm_Data_Len"));
  RS4SIM_GSD_TRY(b.module.prm, b.prm.finish(file, params, std::nullopt));
  if (b.f_prm.length || !b.f_prm.empty()) {
    RS4SIM_GSD_TRY(auto f, b.f_prm.finish(file, params, std::nullopt));
    b.module.f_prm = std::move(f);
  }
  return std::move(b.module);
}

}  // namespace rs4sim::gsd::detail
