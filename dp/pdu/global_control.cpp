// Global_Control, [IEC 61158-6-3 Global_Control].
#include "dp/pdu/global_control.h"

#include "dp/pdu/wire.h"

namespace rs4sim::dp::pdu {

std::uint8_t GlobalControl::control_command() const {
  return static_cast<std::uint8_t>(wire::flag(clear_data, 1) | wire::flag(unfreeze, 2) |
                                   wire::flag(freeze, 3) | wire::flag(unsync, 4) |
                                   wire::flag(sync, 5) | (reserved & 0xC1U));
}

Result<GlobalControl> decode_global_control(std::span<const std::uint8_t> du) {
  if (du.size() < 2) return PduError::kTooShort;
  if (du.size() > 2) return PduError::kTooLong;
  const std::uint8_t c = du[0];
  GlobalControl gc;
  gc.clear_data = wire::bit(c, 1);
  gc.unfreeze = wire::bit(c, 2);
  gc.freeze = wire::bit(c, 3);
  gc.unsync = wire::bit(c, 4);
  gc.sync = wire::bit(c, 5);
  gc.reserved = static_cast<std::uint8_t>(c & 0xC1U);
  gc.group_select = du[1];
  return gc;
}

Result<void> encode_global_control(const GlobalControl& gc, fdl::DataUnit& out) {
  return wire::append(out, {gc.control_command(), gc.group_select});
}

}  // namespace rs4sim::dp::pdu
