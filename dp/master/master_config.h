#pragma once
// Configuration of the class 1 master and of each slave it polls
// ([IEC 61158-6-3 Set_Prm] Set_Prm, [IEC 61158-6-3 Chk_Cfg/Get_Cfg] Chk_Cfg,
// [IEC 61158-6-3 DPV1_Status] DPV1 status, [IEC 61158-6-3 class 1 master]).
//
// A GSD-driven configurator fills these entries; the master only validates them once
// (`validate`) and sends the bytes as they are.

#include "dp/fdl/telegram.h"
#include "dp/master/bus_parameters.h"
#include "dp/pdu/set_prm.h"
#include "dp/time/clock.h"

#include <chrono>
#include <cstdint>
#include <system_error>
#include <vector>

namespace rs4sim::dp::master {

using namespace std::chrono_literals;

struct SlaveEntry {
  std::uint8_t address = 3;  // 0..125 ([IEC 61158-4-3 addresses, SAPs])
  // Set_Prm ([IEC 61158-6-3 Set_Prm]): Station_Status (Lock_Req, WD_On, Sync/Freeze_Req), WD
  // factors, min TSDR, Ident_Number, Group_Ident, DPV1_Status bytes ([IEC 61158-6-3 DPV1_Status])
  // and User_Prm_Data.
  pdu::SetPrm prm;
  // Chk_Cfg identifiers in slot order ([IEC 61158-6-3 Chk_Cfg/Get_Cfg]), 1..244 bytes.
  fdl::DataUnit cfg;
  // Data_Exchange image lengths; must equal the sums of the Chk_Cfg identifiers.
  std::size_t input_length = 0;
  std::size_t output_length = 0;
  // Alarm_Ack goes to DSAP 50 instead of 51 (GSD Extra_Alarm_SAP_supp=1,
  // [IEC 61158-6-3 DPV1 alarms]).
  bool extra_alarm_sap = false;
  // DPV1 C1 response timeout (GSD C1_Response_Timeout), counted from the request.
  Duration c1_response_timeout = 1s;

  [[nodiscard]] bool dpv1_enabled() const { return prm.dpv1 && prm.dpv1->dpv1_enable; }
  [[nodiscard]] bool fail_safe() const { return prm.dpv1 && prm.dpv1->fail_safe; }
};

struct MasterConfig {
  std::uint8_t address = 1;  // own FDL address TS, 0..126
  BusParameters bus = BusParameters::defaults_for(BaudRate::k1M5);
  // Target time between the starts of two poll cycles; a cycle that takes longer starts
  // the next one at once.
  Duration cycle_target = 10ms;
  // [IEC 61158-4-3 token, bus start]: listen for TTO and claim the token (`DC TS TS` twice) before
  // the first cycle.
  bool claim_token = true;
  // [IEC 61158-6-3 master start-up of a slave] [pyprofibus dp_master.py] step 0: start each slave
  // with an FDL_Status request.
  bool fdl_status_first = true;
  // Acknowledge alarms automatically (otherwise the user calls acknowledge_alarm()).
  bool auto_alarm_ack = true;
  // [IEC 61158-6-3 master start-up of a slave] [pyprofibus dp_master.py] step 4: time allowed from
  // Chk_Cfg until Slave_Diag shows the slave ready (pyprofibus WDXRDY 1 s).
  Duration ready_timeout = 1s;
  // Period of the Global_Control Operate/Clear broadcast ([IEC 61158-6-3 class 1 master cycle]); 0
  // = only on request.
  Duration global_control_interval = 0s;
  std::vector<SlaveEntry> slaves;  // up to 125, polled in this order
};

// Checks a slave entry (address range, Set_Prm length ≤ 244, Chk_Cfg 1..244 bytes and
// consistent with input_length/output_length, image lengths ≤ 244, timeout > 0).
std::error_code validate(const SlaveEntry& s);
// Checks the master address, the bus parameters, every slave and that slave addresses
// are unique and differ from the master's.
std::error_code validate(const MasterConfig& m);

// WD_Fact_1/WD_Fact_2 for a watchdog time ([IEC 61158-6-3 Set_Prm]: T_WD = base · F1 · F2 with base
// 10 ms, or 1 ms when `base_1ms`). Rounds up; clamps to 1..255 each.
struct WatchdogFactors {
  std::uint8_t f1 = 1;
  std::uint8_t f2 = 1;
};
WatchdogFactors watchdog_factors(std::chrono::milliseconds t, bool base_1ms = false);

}  // namespace rs4sim::dp::master
