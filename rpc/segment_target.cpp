#include "rpc/segment_target.h"

namespace rs4sim::rpc {

std::vector<std::uint8_t> SegmentTarget::addresses() const { return {segment_.rs4_address()}; }

rs4::device::Rs4Device* SegmentTarget::device(std::uint8_t address) {
  return address == segment_.rs4_address() ? &segment_.device() : nullptr;
}

bool SegmentTarget::run_until(const std::function<bool()>& done, dp::Duration limit) {
  return segment_.run_until(done, limit);
}

void SegmentTarget::after(dp::Duration delay, std::function<void()> f) {
  segment_.run_for(delay);
  f();
}

}  // namespace rs4sim::rpc
