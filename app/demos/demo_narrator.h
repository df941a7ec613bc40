#pragma once
// Human-readable one-line meaning of a DP telegram, for the narrated demos
// (app/demos/narration.h). Names follow [IEC 61158-4-3 frame control]
// [IEC 61158-6-3 SAP assignment, Slave_Diag, MSAC_C1].

#include "app/runtime/run_options.h"
#include "dp/fdl/telegram.h"

#include <string>

namespace rs4sim::app::narrate {

inline std::string diag_flags(std::span<const std::uint8_t> d) {
  if (d.size() < 6) return "short diagnosis";
  std::string s;
  const auto add = [&](bool on, const char* name) {
    if (on) s += std::string(s.empty() ? "" : ", ") + name;
  };
  add(d[0] & 0x02, "Station_Not_Ready");
  add(d[0] & 0x04, "Cfg_Fault");
  add(d[0] & 0x08, "Ext_Diag");
  add(d[0] & 0x10, "Not_Supported");
  add(d[0] & 0x40, "Prm_Fault");
  add(d[1] & 0x01, "Prm_Req");
  add(d[1] & 0x02, "Stat_Diag");
  add(d[1] & 0x08, "WD_On");
  if (s.empty()) s = "ready";
  char master[8];
  std::snprintf(master, sizeof master, "%02X", d[3]);
  s += std::string("; Master_Add ") + master;
  if (d.size() > 6) s += "; ext " + hex(d.subspan(6));
  return s;
}

inline std::string dpv1(std::span<const std::uint8_t> p, bool request) {
  if (p.empty())
    return request ? "DPV1 poll (waiting for the response, "
                     "[IEC 61158-6-3 MSAC_C1 polling])"
                   : "DPV1 empty";
  const std::string args =
      p.size() >= 4 ? " slot " + std::to_string(p[1]) + " index " + std::to_string(p[2]) : "";
  switch (p[0]) {
    case 0x5E:
      return request ? "DPV1 Read.req" + args + " max " + std::to_string(p[3])
                     : "DPV1 Read.res+" + args + " data " + hex(p.subspan(4));
    case 0x5F:
      return request ? "DPV1 Write.req" + args + " data " +
                           hex(p.subspan(std::min<std::size_t>(4, p.size())))
                     : "DPV1 Write.res+" + args;
    case 0x5C:
      return std::string(request ? "Alarm_Ack.req" : "Alarm_Ack.res+") + " slot " +
             std::to_string(p.size() > 1 ? p[1] : 0) + " type " +
             std::to_string(p.size() > 2 ? p[2] : 0);
    default: break;
  }
  if (p[0] & 0x80) return "DPV1 negative response " + hex(p);
  return "DPV1 PDU " + hex(p);
}

inline std::string request(const dp::fdl::Telegram& t) {
  const std::span<const std::uint8_t> du(t.data.data(), t.data.size());
  if (t.type == dp::fdl::FrameType::kToken) return "token";
  if (t.fc.function() == dp::fdl::RequestFunction::kFdlStatus) return "FDL_Status request";
  if (!t.dsap) return "Data_Exchange, outputs " + (du.empty() ? std::string("none") : hex(du));
  switch (*t.dsap) {
    case 60: return "Slave_Diag request";
    case 61: return "Set_Prm " + hex(du);
    case 62: return "Chk_Cfg " + hex(du);
    case 59: return "Get_Cfg request";
    case 58: return "Global_Control " + hex(du);
    case 50:
    case 51: return dpv1(du, true);
    default: return "request to SAP " + std::to_string(*t.dsap);
  }
}

inline std::string response(const dp::fdl::Telegram& t) {
  const std::span<const std::uint8_t> du(t.data.data(), t.data.size());
  if (t.type == dp::fdl::FrameType::kShortAck) return "SC (short acknowledgement)";
  const auto st = t.fc.status();
  if (st == dp::fdl::ResponseStatus::kSapNotEnabled) return "RS: service not activated";
  if (!t.ssap && du.empty()) return "FDL_Status reply (station type slave)";
  const char* prio = st == dp::fdl::ResponseStatus::kDataHigh ? " [DH: diagnosis pending]" : "";
  if (!t.ssap) return "Data_Exchange reply, inputs " + hex(du) + prio;
  if (*t.ssap == 60) return "Slave_Diag: " + diag_flags(du);
  if (*t.ssap == 59) return "Get_Cfg: " + hex(du);
  if (*t.ssap == 51 || *t.ssap == 50) return dpv1(du, false);
  return "reply from SAP " + std::to_string(*t.ssap) + prio;
}

inline std::string describe(const dp::fdl::Telegram& t) {
  const bool is_request = t.type == dp::fdl::FrameType::kToken ||
                          (t.type != dp::fdl::FrameType::kShortAck && t.fc.is_request());
  return is_request ? request(t) : response(t);
}

}  // namespace rs4sim::app::narrate
