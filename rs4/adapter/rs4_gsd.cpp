#include "rs4/adapter/rs4_gsd.h"

#include "gsd/config.h"
#include "gsd/device_gsd.h"
#include "gsd/dp_slave_config.h"

#include <algorithm>
#include <stdexcept>

namespace rs4sim::rs4::adapter {

namespace {

constexpr std::size_t kPduBytes = 5;          // PROFIsafe V1 with a 2-byte CRC2 [RS4 manual §5.1]
constexpr std::size_t kFParameterBytes = 10;  // [IEC 61784-3-3 F-Parameters], CRC1 included

// The built-in file parses (tests/gsd/shipped_gsd_test.cpp); value() throws otherwise.
const gsd::Device& device() { return gsd::rs4sim_device().value(); }

}  // namespace

std::uint16_t ident_number() { return device().ident_number; }

std::uint16_t f_dest_add(std::uint8_t address) {
  static const std::uint16_t base = [] {
    for (const auto& [number, p] : device().params) {
      if (p.name == "F_Dest_Add") return static_cast<std::uint16_t>(p.min);
    }
    throw std::logic_error("built-in GSD: no F_Dest_Add parameter");
  }();
  return static_cast<std::uint16_t>(base + address);
}

namespace {

dp::slave::Config slave_of(const gsd::Device& d, std::uint8_t address) {
  dp::slave::Config s = gsd::dp_slave_config(d, address);
  s.c2_rm_send_timeout = d.dpv1.c2_response_timeout;
  // Alarm_Sequence_Mode_Count: alarms outstanding and Seq_Nr cycle ([IEC 61158-6-3 DPV1 alarms]).
  s.alarm_sequence_numbers = d.dpv1.alarm_sequence_mode_count;
  return s;
}

gsd::Error profile_error(gsd::GsdError code, const std::string& file, std::string message) {
  gsd::Error e;
  e.code = code;
  e.file = file;
  e.message = std::move(message);
  return e;
}

}  // namespace

dp::slave::Config slave_config(std::uint8_t address) { return slave_of(device(), address); }

dp::slave::Config GsdProfile::slave_at(std::uint8_t address) const {
  dp::slave::Config s = slave;
  s.address = address;
  return s;
}

const GsdProfile& builtin_profile() {
  static const GsdProfile p = [] {
    auto r = gsd_profile(device(), std::string(gsd::kRs4simModuleName),
                         std::string(gsd::kRs4simGsdFileName) + " (built in)");
    if (!r) throw std::logic_error("built-in GSD: " + r.error().what());
    return std::move(r).value();
  }();
  return p;
}

gsd::Result<GsdProfile> gsd_profile(const gsd::Device& device, const std::string& module,
                                    const std::string& file) {
  gsd::ConfigRequest request;
  if (!module.empty()) request.modules = {module};
  RS4SIM_GSD_TRY(const gsd::SlaveSetup setup, gsd::configure(device, request));
  const std::string name = setup.modules.empty() ? std::string() : setup.modules.front();
  if (setup.modules.size() != 1) {
    return profile_error(gsd::GsdError::kModuleCount, file,
                         "the RS4/PROFIsafe is one module; choose it with --module");
  }
  if (setup.input_len != kPduBytes || setup.output_len != kPduBytes) {
    return profile_error(
        gsd::GsdError::kBadValue, file,
        "module \"" + name + "\" exchanges " + std::to_string(setup.input_len) + " input and " +
            std::to_string(setup.output_len) +
            " output bytes; the RS4/PROFIsafe exchanges 5 each way (the PROFIsafe V1 PDU: data, "
            "status/control, consecutive number, CRC2) [RS4 manual §5.1]");
  }
  if (setup.f_parameters.size() != 1) {
    return profile_error(gsd::GsdError::kFParameterLayout, file,
                         "module \"" + name +
                             "\" has no F-parameter block (F_Ext_User_Prm_Data_Const/Ref): the "
                             "RS4/PROFIsafe is parametrised by one [RS4 manual §6.2]");
  }
  const std::size_t dpv1 = setup.dpv1 ? 3 : 0;  // DPV1_Status_1..3 are not User_Prm_Data here
  const std::size_t f_params = setup.f_parameters.front().offset;
  if (f_params < dpv1 + 4 || f_params + kFParameterBytes > setup.user_prm_data.size()) {
    return profile_error(gsd::GsdError::kFParameterLayout, file,
                         "the F-parameters of module \"" + name +
                             "\" do not follow a 4-byte block header [IEC 61158-6-3 Set_Prm, "
                             "Prm_Structure]");
  }
  GsdProfile p;
  p.file = file;
  p.module = name;
  p.slave = slave_of(device, 0);
  p.cfg = setup.cfg;
  p.user_prm_len = setup.user_prm_data.size() - dpv1;
  p.f_block_offset = f_params - 4 - dpv1;
  std::copy_n(setup.user_prm_data.begin() + static_cast<std::ptrdiff_t>(f_params - 4), 4,
              p.f_block_header.begin());
  if (p.f_block_header[0] != 4 + kFParameterBytes) {
    return profile_error(gsd::GsdError::kFParameterLayout, file,
                         "the F-parameter block of module \"" + name +
                             "\" does not start with its length 14 (0x0E) [IEC 61158-6-3 "
                             "Set_Prm, Prm_Structure]");
  }
  return p;
}

}  // namespace rs4sim::rs4::adapter
