#pragma once
// The RS4/PROFIsafe's PROFIsafe profile [RS4 manual §4.5, §6.2]: what its F-device accepts
// in the F-parameter block, and its F_Dest_Add = 500 + PROFIBUS address. The one place
// the rule "500 + address" is written; the app and the adapter call it.

#include "profisafe/f_parameters.h"

#include <cstdint>

namespace rs4sim::rs4::safety {

inline constexpr std::uint16_t kFDestAddBase = 500;
inline constexpr unsigned kMaxDpAddress = 126;

// F_Dest_Add of the RS4 at a DP address: the 16-bit sum 500 + address [RS4 manual §4.5];
// 0 (no valid F_Dest_Add) for addresses above 126, which are not DP station addresses.
[[nodiscard]] constexpr std::uint16_t f_dest_add(unsigned dp_address) noexcept {
  return dp_address <= kMaxDpAddress ? static_cast<std::uint16_t>(kFDestAddBase + dp_address)
                                     : std::uint16_t{0};
}

// The RS4 at a DP address: SIL2, 2-byte CRC, block 0, V1, F_WD_Time 10..1000 ms,
// F_Source_Add 1..65534, F_Dest_Add = f_dest_add(dp_address).
[[nodiscard]] profisafe::DeviceProfile device_profile(unsigned dp_address) noexcept;

}  // namespace rs4sim::rs4::safety
