#include "dp/devices/generic_master_config.h"

#include "dp/pdu/cfg.h"

namespace rs4sim::dp::devices {

master::SlaveEntry master_entry_for(const GenericSlaveConfig& slave,
                                    std::chrono::milliseconds watchdog) {
  auto summary = pdu::summarize_cfg(slave.cfg, pdu::CfgService::kChkCfg);
  if (!summary) throw std::system_error(summary.error(), "generic slave configuration");
  master::SlaveEntry m;
  m.address = slave.address;
  m.prm.station_status.lock_req = true;
  m.prm.station_status.wd_on = true;
  const auto f = master::watchdog_factors(watchdog);
  m.prm.wd_fact_1 = f.f1;
  m.prm.wd_fact_2 = f.f2;
  m.prm.min_tsdr = 11;
  m.prm.ident_number = slave.ident_number;
  if (slave.dpv1) {
    pdu::Dpv1Status d;
    d.dpv1_enable = true;
    d.enable_diagnostic_alarm = true;
    d.enable_process_alarm = true;
    m.prm.dpv1 = d;
  }
  m.cfg.assign(slave.cfg.begin(), slave.cfg.end());
  m.input_length = summary.value().input_bytes;
  m.output_length = summary.value().output_bytes;
  return m;
}

}  // namespace rs4sim::dp::devices
