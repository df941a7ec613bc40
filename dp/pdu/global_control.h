#pragma once
// Global_Control (DSAP 58, DA 127, SDN), [IEC 61158-6-3 Global_Control].
// DU: [0] Control_Command [1] Group_Select.

#include "dp/fdl/telegram.h"
#include "dp/pdu/errors.h"

#include <cstdint>
#include <span>

namespace rs4sim::dp::pdu {

struct GlobalControl {
  bool clear_data = false;        // bit 1
  bool unfreeze = false;          // bit 2
  bool freeze = false;            // bit 3
  bool unsync = false;            // bit 4
  bool sync = false;              // bit 5
  std::uint8_t reserved = 0;      // bits 0, 6, 7 in place (mask 0xC1)
  std::uint8_t group_select = 0;  // 0 = all slaves

  [[nodiscard]] std::uint8_t control_command() const;
  // Executed by a slave with `group_ident` (from Set_Prm): Group_Select 0 or a common bit.
  [[nodiscard]] bool addresses(std::uint8_t group_ident) const {
    return group_select == 0 || (group_select & group_ident) != 0;
  }
  friend bool operator==(const GlobalControl&, const GlobalControl&) = default;
};

// Errors: kTooShort (< 2), kTooLong (> 2).
Result<GlobalControl> decode_global_control(std::span<const std::uint8_t> du);
Result<void> encode_global_control(const GlobalControl& gc, fdl::DataUnit& out);

}  // namespace rs4sim::dp::pdu
