#include "dp/master/master_config.h"

#include "dp/master/master_error.h"
#include "dp/master/reply.h"
#include "dp/pdu/cfg.h"
#include "dp/pdu/sap.h"

#include <array>

namespace rs4sim::dp::master {

std::error_code validate(const SlaveEntry& s) {
  const auto bad = make_error_code(MasterError::kBadSlaveConfig);
  if (s.address > pdu::sap::kMaxSlaveAddress) return bad;
  fdl::DataUnit prm;
  if (!pdu::encode_set_prm(s.prm, prm)) return bad;
  if (s.input_length > fdl::kMaxDataUnit - 2 || s.output_length > fdl::kMaxDataUnit - 2) {
    return bad;  // 244-byte images ([IEC 61158-6-3 Chk_Cfg/Get_Cfg])
  }
  const auto summary = pdu::summarize_cfg(bytes(s.cfg), pdu::CfgService::kChkCfg);
  if (!summary) return bad;
  if (summary.value().input_bytes != s.input_length ||
      summary.value().output_bytes != s.output_length) {
    return bad;
  }
  if (s.c1_response_timeout <= Duration::zero()) return bad;
  if (s.prm.dpv1 && s.prm.dpv1->alarm_mode > 7) return bad;
  return {};
}

std::error_code validate(const MasterConfig& m) {
  if (m.address > 126) return make_error_code(MasterError::kBadMasterAddress);
  if (auto ec = validate(m.bus)) return ec;
  if (m.cycle_target < Duration::zero() || m.ready_timeout <= Duration::zero() ||
      m.global_control_interval < Duration::zero()) {
    return make_error_code(MasterError::kBadSlaveConfig);
  }
  std::array<bool, 128> seen{};
  seen[m.address] = true;
  for (const SlaveEntry& s : m.slaves) {
    if (auto ec = validate(s)) return ec;
    if (seen[s.address]) return make_error_code(MasterError::kDuplicateSlave);
    seen[s.address] = true;
  }
  return {};
}

WatchdogFactors watchdog_factors(std::chrono::milliseconds t, bool base_1ms) {
  const long long base = base_1ms ? 1 : 10;
  long long units = (t.count() + base - 1) / base;
  if (units < 1) units = 1;
  if (units > 255LL * 255LL) units = 255LL * 255LL;
  // Smallest F1 such that F2 = ceil(units / F1) fits into one byte.
  const long long f1 = (units + 254) / 255;
  const long long f2 = (units + f1 - 1) / f1;
  return {static_cast<std::uint8_t>(f1), static_cast<std::uint8_t>(f2)};
}

}  // namespace rs4sim::dp::master
