// PROFIsafe F-modules of a GSD ([PROFIBUS GSD spec F-parameter keywords] [IEC 61784-3-3
// F-Parameters, safety PDU]). See f_module.h.
#include "gsd/f_module.h"

#include "gsd/syntax.h"

#include <array>
#include <string_view>

namespace rs4sim::gsd {
namespace {

// The values the PROFIsafe profile gives each named F-parameter ([IEC 61784-3-3 F-Parameters]):
// F_SIL 3 = NoSIL, F_CRC_Length 3 is reserved, F_Par_Version 0 = V1 and 1 = V2, addresses 0 and
// 65535 are invalid, F_WD_Time 0 is no watchdog.
struct ProfileRange {
  std::string_view name;
  std::int64_t lo, hi;
};
constexpr std::array<ProfileRange, 10> kProfileRanges{{
    {"F_Check_SeqNr", 0, 1},
    {"F_Check_iPar", 0, 1},
    {"F_SIL", 0, 3},
    {"F_CRC_Length", 0, 2},
    {"F_Block_ID", 0, 7},
    {"F_Par_Version", 0, 1},
    {"F_Source_Add", 1, 65534},
    {"F_Dest_Add", 1, 65534},
    {"F_WD_Time", 1, 65535},
    {"F_Par_CRC", 0, 65535},
}};

// F-data each way in the short format (V1, V2 with a 3-byte CRC2) and the long one (V2, 4-byte
// CRC2) ([IEC 61784-3-3 safety PDU]).
constexpr std::size_t kMaxShortData = profisafe::kMaxDataSize;
constexpr std::size_t kMaxLongData = 123;

Error layout_error(std::string message) {
  return Error{GsdError::kFParameterLayout, "", 0, "", std::move(message)};
}

Result<std::size_t> f_data(const Module& m, std::size_t cfg_bytes, const SafetyIoLayout& io,
                           std::string_view direction) {
  const std::size_t max = io.crc2_bytes == 4 ? kMaxLongData : kMaxShortData;
  if (cfg_bytes < io.overhead() || cfg_bytes - io.overhead() > max) {
    return layout_error("module \"" + m.name + "\": " + std::string(direction) + " of " +
                        std::to_string(cfg_bytes) + " bytes (Cfg) hold no safety PDU of " +
                        std::to_string(io.overhead()) + " bytes overhead and 0.." +
                        std::to_string(max) + " bytes F-data");
  }
  return cfg_bytes - io.overhead();
}

Error located(Error e, const Device& d, int line) {
  e.file = d.file;
  e.line = line;
  return e;
}

// An F-parameter whose default the profile does not allow.
Result<void> check_profile_ranges(const Device& d, const Module& m) {
  for (const auto& ref : m.f_prm->refs) {
    const ExtParam& p = d.params.at(ref.param);
    for (const auto& r : kProfileRanges) {
      if (!syntax::iequals(p.name, r.name)) continue;
      if (p.default_value < r.lo || p.default_value > r.hi) {
        return Error{GsdError::kOutOfRange, d.file, p.line, "",
                     "module \"" + m.name + "\": " + p.name + " default " +
                         std::to_string(p.default_value) + " is outside PROFIsafe's " +
                         std::to_string(r.lo) + ".." + std::to_string(r.hi)};
      }
    }
  }
  return boost::outcome_v2::success();
}

}  // namespace

bool is_f_module(const Module& m) noexcept {
  return m.f_prm || m.f_param_desc_crc || m.f_io_structure_desc_crc;
}

Result<SafetyIoLayout> safety_io_layout(const Module& m, const profisafe::FParameters& p) {
  if (!profisafe::is_supported_connection(p.par_version, p.crc_length)) {
    return layout_error("module \"" + m.name + "\": F_Par_Version " +
                        std::to_string(p.par_version) + " with F_CRC_Length " +
                        std::to_string(static_cast<unsigned>(p.crc_length)) +
                        " is no PROFIsafe connection (V1: 0 with 1 = 2 bytes; V2: 1 with 0 = "
                        "3 bytes or 2 = 4 bytes)");
  }
  const profisafe::PduConfig pdu = profisafe::PduConfig::from(p, 0);
  SafetyIoLayout io;
  io.version = pdu.version;
  io.crc2_bytes = profisafe::crc2_size(pdu);
  io.number_bytes = pdu.version == profisafe::ProtocolVersion::kV1 ? 1 : 0;
  RS4SIM_GSD_TRY(io.f_input_bytes, f_data(m, m.input_len, io, "inputs"));
  RS4SIM_GSD_TRY(io.f_output_bytes, f_data(m, m.output_len, io, "outputs"));
  return io;
}

// "PROFIsafe V1, CRC2 2 bytes + consecutive number; F-inputs 1 byte, F-outputs 1 byte"
std::string to_text(const SafetyIoLayout& io) {
  const bool v1 = io.version == profisafe::ProtocolVersion::kV1;
  return std::string("PROFIsafe ") + (v1 ? "V1" : "V2") + ", CRC2 " +
         std::to_string(io.crc2_bytes) + " bytes" +
         (v1 ? " + consecutive number" : " (virtual consecutive number)") + "; F-inputs " +
         std::to_string(io.f_input_bytes) + " bytes, F-outputs " +
         std::to_string(io.f_output_bytes) + " bytes, each + status/control byte + CRC2";
}

Result<FModuleInfo> describe_f_module(const Device& d, const Module& m) {
  FModuleInfo info;
  RS4SIM_GSD_TRY(info.defaults, f_parameter_defaults(d, m));
  const auto parsed = profisafe::parse_f_parameters(info.defaults.block);
  if (!parsed) return layout_error("module \"" + m.name + "\": " + parsed.error().message());
  info.parameters = parsed.value();
  for (const auto& ref : m.f_prm->refs) info.fields.push_back({ref.offset, &d.params.at(ref.param)});
  RS4SIM_GSD_TRY(info.io, safety_io_layout(m, info.parameters));
  return info;
}

Result<void> check_f_modules(const Device& d) {
  for (const auto& m : d.modules) {
    if (!is_f_module(m)) continue;
    if (!m.f_prm || m.f_prm->refs.empty()) {
      return Error{GsdError::kMissingKeyword, d.file, m.line, "",
                   "module \"" + m.name +
                       "\" is an F-module but has no F-parameter description "
                       "(F_Ext_Module_Prm_Data_Len, F_Ext_User_Prm_Data_Ref)"};
    }
    RS4SIM_GSD_TRYV(check_profile_ranges(d, m));
    auto info = describe_f_module(d, m);
    if (!info) return located(std::move(info).error(), d, m.line);
  }
  return boost::outcome_v2::success();
}

}  // namespace rs4sim::gsd
