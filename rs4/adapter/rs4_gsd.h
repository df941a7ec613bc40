#pragma once
// The RS4/PROFIsafe facts its built-in GSD declares (gsd/files/RSIM5234.gsd, parsed once by
// gsd::rs4sim_device()): the one source for the ident number, the F_Dest_Add rule and the
// DP slave settings, instead of hand copies beside the file.

#include "dp/slave/slave_config.h"

#include <cstdint>

namespace rs4sim::rs4::adapter {

// GSD Ident_Number (0x5234, the project's own choice: docs/gsd.md).
[[nodiscard]] std::uint16_t ident_number();

// F_Dest_Add the RS4 accepts at a PROFIBUS address: the lowest value of the GSD's
// F_Dest_Add range (500) + address [RS4 manual §2].
[[nodiscard]] std::uint16_t f_dest_add(std::uint8_t address);

// The dp::slave::Slave features the GSD declares (DPV1, C1/C2 lengths, C2 response timeout,
// alarms in sequence mode, diagnosis length, no Sync/Freeze/Fail_Safe), at `address`.
[[nodiscard]] dp::slave::Config slave_config(std::uint8_t address);

}  // namespace rs4sim::rs4::adapter
