// The keywords of the GSD specification ([PROFIBUS GSD spec] revisions 1–5, slave and
// master keywords), for telling a keyword a master simply does not need (skipped silently)
// from a word that is not a GSD keyword at all (a misspelling such as `Unit_Diag_!Bit`,
// skipped with a warning, as engineering tools do).
#include "gsd/syntax.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <string>

namespace rs4sim::gsd::syntax {
namespace {

// Lower case, sorted at first use.
constexpr std::array<std::string_view, 223> kKeywords{{
    // identification and general station keywords
    "gsd_revision", "vendor_name", "model_name", "revision", "revision_number", "ident_number",
    "protocol_ident", "station_type", "fms_supp", "hardware_release", "software_release",
    "ordernumber", "info_text", "redundancy", "repeater_ctrl_sig", "24v_pins",
    "implementation_type", "bitmap_device", "bitmap_diag", "bitmap_sf", "slave_family",
    "periphery", "physical_layer", "physical_interface", "end_physical_interface",
    "webpage", "vendor_address", "manufacturer_id",
    // baud rates (MaxTsdr_, Transmission_Delay_, Reaction_Delay_ are prefixes below)
    "9.6_supp", "19.2_supp", "31.25_supp", "45.45_supp", "93.75_supp", "187.5_supp",
    "500_supp", "1.5m_supp", "3m_supp", "6m_supp", "12m_supp",
    // slave keywords
    "freeze_mode_supp", "sync_mode_supp", "auto_baud_supp", "set_slave_add_supp",
    "min_slave_intervall", "modular_station", "max_module", "max_input_len", "max_output_len",
    "max_data_len", "modul_offset", "fail_safe", "fail_safe_required", "max_diag_data_len",
    "diag_update_delay", "user_prm_data_len", "user_prm_data", "max_user_prm_data_len",
    "ext_user_prm_data_const", "ext_user_prm_data_ref", "ext_module_prm_data_len",
    "x_ext_module_prm_data_len", "prm_text_ref", "changeable", "visible", "text",
    "prmtext", "endprmtext", "extuserprmdata", "endextuserprmdata", "bit", "bitarea",
    "unsigned8", "unsigned16", "unsigned32", "signed8", "signed16", "signed32", "octetstring",
    "visiblestring", "module", "endmodule", "preset", "fixpresetmodules", "data_area_beg",
    "data_area_end",
    "area_name", "related_cfg_identifier", "io_direction", "length", "consistency",
    "publisher_allow", "dp_master_trigger", "data_type", "slotdefinition", "slot",
    "endslotdefinition", "max_iparameter_size", "iparameter_sub_slot", "ident_maintenance_supp",
    "time_sync_supp", "slave_max_switch_over_time", "slave_redundancy_supp",
    "isochron_mode_supp", "isochron_mode_required", "isochron_mode_synchronised", "tbase_dp",
    "tdp_min", "tdp_max", "t_pll_w_max", "tbase_io", "ti_min", "to_min", "max_bus_cycle",
    "prmcmd_supp", "subsys_dir_index", "dxb_max_link_count", "dxb_max_data_length",
    "dxb_subscribertable_block_location", "ident_maintenance_required",
    // diagnosis texts
    "unit_diag_bit", "unit_diag_not_bit", "unit_diag_bit_help", "unit_diag_not_bit_help",
    "unit_diag_area", "unit_diag_area_end", "value", "value_help", "unit_diag_type",
    "unitdiagtype", "endunitdiagtype", "x_unit_diag_bit", "x_unit_diag_not_bit",
    "x_unit_diag_bit_help", "x_unit_diag_not_bit_help", "x_unit_diag_area",
    "x_unit_diag_area_end", "x_value", "x_value_help", "channel_diag", "channel_diag_help",
    "x_channel_diag", "x_channel_diag_help",
    // DP-V1
    "dpv1_slave", "c1_read_write_supp", "c1_max_data_len", "c1_response_timeout",
    "c1_read_write_required", "c2_read_write_supp", "c2_max_data_len", "c2_response_timeout",
    "c2_read_write_required", "c2_max_count_channels", "max_initiate_pdu_length",
    "diagnostic_alarm_supp", "process_alarm_supp", "pull_plug_alarm_supp", "status_alarm_supp",
    "update_alarm_supp", "manufacturer_specific_alarm_supp", "extra_alarm_sap_supp",
    "alarm_sequence_mode_count", "alarm_type_mode_supp", "diagnostic_alarm_required",
    "process_alarm_required", "pull_plug_alarm_required", "status_alarm_required",
    "update_alarm_required", "manufacturer_specific_alarm_required", "dpv1_data_types",
    "wd_base_1ms_supp", "check_cfg_mode", "publisher_supp", "prm_block_structure_supp",
    "prm_block_structure_req", "prm_structure_supp", "prm_structure_req",
    // PROFIsafe
    "f_ext_module_prm_data_len", "f_ext_user_prm_data_const", "f_ext_user_prm_data_ref",
    "f_paramdesccrc", "f_io_structuredesccrc", "f_io_structuredescversion", "f_extuserprmdata",
    "f_endextuserprmdata",
    // master keywords (a class 1 master's GSD)
    "master_freeze_mode_supp", "master_sync_mode_supp", "master_fail_safe_supp",
    "download_supp", "upload_supp", "act_para_brct_supp", "act_param_supp", "max_mps_length",
    "max_lsdu_ms", "max_lsdu_mm", "min_poll_timeout", "las_len", "max_slaves_supp",
    "max_master_input_len", "max_master_output_len", "max_master_data_len", "dpv1_master",
    "dpv1_conformance_class", "c1_master_read_write_supp", "master_dpv1_alarm_supp",
    "master_diagnostic_alarm_supp", "master_process_alarm_supp", "master_pull_plug_alarm_supp",
    "master_status_alarm_supp", "master_update_alarm_supp",
    "master_manufacturer_specific_alarm_supp", "master_extra_alarm_sap_supp",
    "master_alarm_sequence_mode", "master_alarm_type_mode", "master_freeze_mode_supp_2",
    "max_mps_length_2", "isochron_mode_master_supp", "dxb_master_supp", "x_prm_sap_supp",
    "x_max_user_prm_data_len", "x_ext_user_prm_data_const", "x_ext_user_prm_data_ref",
    "master_user_data_len", "master_user_data",
}};

// Families of keywords named by a baud rate or a numbered suffix.
constexpr std::array<std::string_view, 7> kPrefixes{{
    "maxtsdr_", "transmission_delay_", "reaction_delay_", "trdy_", "tqui_", "tset_", "tsdi_"}};

}  // namespace

bool is_gsd_keyword(std::string_view keyword) {
  std::string k(keyword);
  for (auto& c : k) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  static const auto sorted = [] {
    auto copy = kKeywords;
    std::sort(copy.begin(), copy.end());
    return copy;
  }();
  if (std::binary_search(sorted.begin(), sorted.end(), std::string_view(k))) return true;
  return std::any_of(kPrefixes.begin(), kPrefixes.end(), [&](std::string_view p) {
    return k.size() > p.size() && k.compare(0, p.size(), p) == 0;
  });
}

}  // namespace rs4sim::gsd::syntax
