#pragma once
// The DP slave settings a GSD file declares, as the slave stack's configuration: one mapping
// for every slave configured from a GSD (the RS4's built-in file, a user's GSD station).

#include "dp/slave/slave_config.h"
#include "gsd/model.h"

#include <cstdint>

namespace rs4sim::gsd {

// Ident_Number, Sync/Freeze/Set_Slave_Add support, Max_Diag_Data_Len, the DPV1 status and
// C1/C2 services, Fail_Safe, WD_Base_1ms ([PROFIBUS GSD spec] [IEC 61158-6-3 Set_Prm,
// DPV1_Status]); a C1/C2 maximum length or Alarm_Sequence_Mode_Count of 0 (not declared)
// keeps the stack's default.
dp::slave::Config dp_slave_config(const Device& d, std::uint8_t address);

}  // namespace rs4sim::gsd
