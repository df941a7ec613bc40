#pragma once
// The rs4sim virtual RS4/PROFIsafe's own GSD (gsd/files/RSIM5234.gsd), compiled into the
// library so that `rs4sim gsd` and the app layer work without the source tree.
// Ident_Number 0x5234 is the rs4sim project's own choice, not a number assigned by PI
// and not Leuze's (docs/gsd.md).

#include "gsd/error.h"
#include "gsd/model.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace rs4sim::gsd {

inline constexpr std::uint16_t kRs4simIdentNumber = 0x5234;  // ASCII "R4"
inline constexpr std::string_view kRs4simGsdFileName = "RSIM5234.gsd";
inline constexpr std::string_view kRs4simModuleName = "RS4/PROFIsafe F-I/O (1 byte)";

// The layout docs/gsd.md documents, for the slave side (the RS4 adapter checks Set_Prm
// and Chk_Cfg against it). Offsets are in User_Prm_Data (= Set_Prm DU offset - 7).
inline constexpr std::size_t kRs4simUserPrmDataLen = 17;
inline constexpr std::array<std::uint8_t, 3> kRs4simDpv1Status{0x80, 0x24, 0x0B};
inline constexpr std::array<std::uint8_t, 4> kRs4simFBlockHeader{0x0E, 0x05, 0x01, 0x00};
inline constexpr std::size_t kRs4simFBlockHeaderOffset = 3;
inline constexpr std::size_t kRs4simFParametersOffset = 7;  // 10 bytes,
                                                            // [IEC 61784-3-3 F-Parameters]
inline constexpr std::array<std::uint8_t, 3> kRs4simCfg{0xC0, 0x84, 0x84};

// The file's bytes exactly as shipped (ASCII, CRLF line ends).
std::string_view rs4sim_gsd_text() noexcept;

// The shipped GSD, parsed (once; the result is shared).
const Result<Device>& rs4sim_device();

}  // namespace rs4sim::gsd
