#include "rpc/segment_plc.h"

namespace rs4sim::rpc {

std::optional<std::uint8_t> SegmentPlc::output_byte(std::uint8_t address) const {
  if (address != segment_.rs4_address()) return std::nullopt;
  return segment_.output_byte();
}

void SegmentPlc::set_output_byte(std::uint8_t address, std::uint8_t out) {
  if (address == segment_.rs4_address()) segment_.set_output_byte(out);
}

bool SegmentPlc::manual_acknowledge(std::uint8_t address) const {
  return address == segment_.rs4_address() && !segment_.auto_ack_rei();
}

void SegmentPlc::set_manual_acknowledge(std::uint8_t address, bool manual) {
  if (address == segment_.rs4_address()) segment_.set_auto_ack_rei(!manual);
}

}  // namespace rs4sim::rpc
