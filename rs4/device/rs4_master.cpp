#include "rs4/device/rs4_master.h"

#include "dp/pdu/set_prm.h"
#include "gsd/device_gsd.h"

#include <strings.h>

#include <algorithm>

namespace rs4sim::rs4::device {

namespace {

bool overrides(const std::vector<gsd::ParamOverride>& list, const char* name) {
  return std::any_of(list.begin(), list.end(), [name](const gsd::ParamOverride& o) {
    return ::strcasecmp(o.name.c_str(), name) == 0;
  });
}

gsd::Error layout_error(std::string message) {
  gsd::Error e;
  e.code = gsd::GsdError::kFParameterLayout;
  e.message = std::move(message);
  return e;
}

}  // namespace

gsd::Result<Rs4MasterEntry> rs4_master_entry(const Rs4MasterOptions& options) {
  const auto& builtin = gsd::rs4sim_device();
  if (options.device == nullptr && !builtin) return builtin.error();
  const gsd::Device& device = options.device != nullptr ? *options.device : builtin.value();
  gsd::ConfigRequest request;
  if (!options.module.empty()) request.modules = {options.module};
  request.overrides = options.overrides;
  if (!overrides(options.overrides, "F_Dest_Add")) {
    request.overrides.push_back({"F_Dest_Add", 500 + options.address});  // [RS4 manual §4.5]
  }
  if (!overrides(options.overrides, "F_WD_Time")) {
    request.overrides.push_back({"F_WD_Time", options.f_wd_time_ms});
  }
  RS4SIM_GSD_TRY(gsd::SlaveSetup config, gsd::configure(device, request));
  if (config.f_parameters.size() != 1)
    return layout_error("the RS4 module needs one F-parameter block");

  // Set_Prm DU = 7 fixed bytes ([RS4 manual §2.3]) + User_Prm_Data (DPV1_Status_1..3 first,
  // [RS4 manual §5.1.1]).
  Rs4MasterEntry entry;
  dp::fdl::DataUnit du;
  dp::pdu::SetPrm fixed;
  fixed.station_status.lock_req = true;
  fixed.station_status.wd_on = true;
  const auto wd = dp::master::watchdog_factors(options.dp_watchdog);
  fixed.wd_fact_1 = wd.f1;
  fixed.wd_fact_2 = wd.f2;
  fixed.min_tsdr = 11;
  fixed.ident_number = config.ident_number;
  if (!dp::pdu::encode_set_prm(fixed, du)) return layout_error("Set_Prm header does not encode");
  du.insert(du.end(), config.user_prm_data.begin(), config.user_prm_data.end());
  auto prm = dp::pdu::decode_set_prm(std::span<const std::uint8_t>(du.data(), du.size()),
                                     config.dpv1 ? dp::pdu::PrmLayout::kDpv1
                                                 : dp::pdu::PrmLayout::kDpv0);
  if (!prm) return layout_error("the GSD's Set_Prm does not decode: " + prm.error().message());

  entry.slave.address = options.address;
  entry.slave.prm = prm.value();
  entry.slave.cfg.assign(config.cfg.begin(), config.cfg.end());
  entry.slave.input_length = config.input_len;
  entry.slave.output_length = config.output_len;
  entry.f_parameters = config.f_parameters.front().parameters;
  entry.gsd = std::move(config);
  if (options.f_par_crc_override) {
    // SetPrm::user_data starts after DPV1_Status_1..3, User_Prm_Data includes them.
    const std::size_t at =
        f_par_crc_offset(entry) - (entry.gsd.dpv1 ? entry.gsd.dpv1_status.size() : 0);
    entry.slave.prm.user_data[at] = static_cast<std::uint8_t>(*options.f_par_crc_override >> 8);
    entry.slave.prm.user_data[at + 1] = static_cast<std::uint8_t>(*options.f_par_crc_override);
  }
  return entry;
}

profisafe::FHostConfig rs4_fhost_config(const Rs4MasterEntry& entry) {
  profisafe::FHostConfig c;
  c.params = entry.f_parameters;
  c.data_size = 1;  // [RS4 manual §5.1]: one byte of process data each way
  return c;
}

std::size_t f_par_crc_offset(const Rs4MasterEntry& entry) {
  return entry.gsd.f_parameters.front().offset + 8;  // F_Par_CRC: block bytes 8..9
}

}  // namespace rs4sim::rs4::device
