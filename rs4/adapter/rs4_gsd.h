#pragma once
// The RS4/PROFIsafe facts its built-in GSD declares (gsd/files/RSIM5234.gsd, parsed once by
// gsd::rs4sim_device()): the one source for the ident number, the F_Dest_Add rule and the
// DP slave settings, instead of hand copies beside the file.

#include "dp/slave/slave_config.h"
#include "gsd/error.h"
#include "gsd/model.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rs4sim::rs4::adapter {

// GSD Ident_Number (0x5234, the project's own choice: docs/gsd.md).
[[nodiscard]] std::uint16_t ident_number();

// F_Dest_Add the RS4 accepts at a PROFIBUS address: the lowest value of the GSD's
// F_Dest_Add range (500) + address [RS4 manual §2].
[[nodiscard]] std::uint16_t f_dest_add(std::uint8_t address);

// The dp::slave::Slave features the GSD declares (DPV1, C1/C2 lengths, C2 response timeout,
// alarms in sequence mode, diagnosis length, no Sync/Freeze/Fail_Safe), at `address`.
[[nodiscard]] dp::slave::Config slave_config(std::uint8_t address);

// What the adapter takes from a GSD: the built-in one, or the user's (`rs4sim run --device
// rs4 --gsd FILE`, docs/gsd.md "The RS4 from your GSD"), so that a PLC project configured with
// the device's own file is accepted as that device would accept it. The RS4's behaviour stays
// the manual's: 5 bytes in and out (the PROFIsafe V1 PDU), the F-parameters checked by its
// F-device, F_Dest_Add = 500 + address [RS4 manual §2, §6.2].
struct GsdProfile {
  std::string file;    // as given, or "RSIM5234.gsd (built in)"
  std::string module;  // the module's GSD name
  dp::slave::Config slave;  // ident, DPV1 and the services the file declares (address 0)
  std::vector<std::uint8_t> cfg;  // the Chk_Cfg DU accepted, exactly the module's Cfg bytes
  // Set_Prm's User_Prm_Data as the slave sees it (after DPV1_Status_1..3 on a DPV1 slave): its
  // length, and where the F-parameter block's 4-byte header (length 14, type, slot, 0) lies,
  // followed by the 10 F-parameters. The other bytes (constants of the file) are not checked,
  // as a GSD station's are not (docs/gsd.md).
  std::size_t user_prm_len = 0;
  std::size_t f_block_offset = 0;
  std::array<std::uint8_t, 4> f_block_header{};

  [[nodiscard]] dp::slave::Config slave_at(std::uint8_t address) const;
};

// The built-in GSD's profile (the default).
[[nodiscard]] const GsdProfile& builtin_profile();

// The profile of `module` (empty: the compact station's one module) of a user's GSD. Errors
// (kBadValue, kUnknownModule, kModuleCount, kFParameterLayout ...; the message names what the
// RS4 needs): the module must exchange 5 bytes each way and carry one PROFIsafe F-parameter
// block; the file's own errors as gsd::configure gives them.
gsd::Result<GsdProfile> gsd_profile(const gsd::Device& device, const std::string& module,
                                    const std::string& file);

}  // namespace rs4sim::rs4::adapter
