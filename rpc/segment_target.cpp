#include "rpc/segment_target.h"

namespace rs4sim::rpc {

SegmentTarget::SegmentTarget(rs4::device::Rs4Segment& segment) : segment_(segment) {
  const auto address = segment.rs4_address();
  hub_->watch(address, segment.device());
  // The bus outlives nothing it calls: the observer holds the hub, not this target.
  segment.bus().add_observer([hub = hub_, address, &segment](const dp::link::BusEvent& e) {
    if (hub->wants_telegrams() && (e.from == address || e.to == address)) {
      const auto direction =
          e.from == address ? v1::DIRECTION_FROM_STATION : v1::DIRECTION_TO_STATION;
      hub->telegram(address, direction, e.wire, dp::link::to_string(e.fate), e.time);
    }
    hub->poll(segment.now());
  });
}

std::vector<std::uint8_t> SegmentTarget::addresses() const { return {segment_.rs4_address()}; }

rs4::device::Rs4Device* SegmentTarget::device(std::uint8_t address) {
  return address == segment_.rs4_address() ? &segment_.device() : nullptr;
}

bool SegmentTarget::run_until(const std::function<bool()>& done, dp::Duration limit) {
  const bool reached = segment_.run_until(done, limit);
  hub_->poll(segment_.now());
  return reached;
}

void SegmentTarget::after(dp::Duration delay, std::function<void()> f) {
  segment_.run_for(delay);
  f();
  hub_->poll(segment_.now());
}

}  // namespace rs4sim::rpc
