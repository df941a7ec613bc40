#pragma once
// The master's configuration entry for polling a generic slave ([IEC 61158-6-3 Set_Prm],
// [IEC 61158-6-3 Chk_Cfg/Get_Cfg, DPV1_Status]): Set_Prm with Lock_Req + WD_On, the slave's ident,
// DPV1_Enable with diagnostic and process alarms (Alarm_Mode 0), no User_Prm_Data; Chk_Cfg = the
// slave's identifiers; image lengths from the identifiers.

#include "dp/devices/generic_slave.h"
#include "dp/master/master_config.h"

namespace rs4sim::dp::devices {

// Throws std::system_error for identifiers that do not parse ([IEC 61158-6-3 Chk_Cfg/Get_Cfg]).
master::SlaveEntry master_entry_for(
    const GenericSlaveConfig& slave,
    std::chrono::milliseconds watchdog = std::chrono::milliseconds(100));

}  // namespace rs4sim::dp::devices
