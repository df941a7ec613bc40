#pragma once
// The rs4sim virtual RS4/PROFIsafe's own GSD (gsd/files/RSIM5234.gsd), compiled into the
// library so that `rs4sim gsd` and the app layer work without the source tree.
// Ident_Number 0x5234 is the rs4sim project's own choice, not a number assigned by PI
// and not Leuze's (docs/gsd.md).

#include "gsd/error.h"
#include "gsd/model.h"

#include <cstdint>
#include <string_view>

namespace rs4sim::gsd {

inline constexpr std::uint16_t kRs4simIdentNumber = 0x5234;  // ASCII "R4"
inline constexpr std::string_view kRs4simGsdFileName = "RSIM5234.gsd";
inline constexpr std::string_view kRs4simModuleName = "RS4/PROFIsafe F-I/O (1 byte)";

// The file's bytes exactly as shipped (ASCII, CRLF line ends).
std::string_view rs4sim_gsd_text() noexcept;

// The shipped GSD, parsed (once; the result is shared).
const Result<Device>& rs4sim_device();

}  // namespace rs4sim::gsd
