#include "rpc/segment_target.h"

#include "rpc/items_watcher.h"
#include "rpc/rs4_state.h"

#include <cstdio>
#include <memory>

namespace rs4sim::rpc {

SegmentTarget::SegmentTarget(rs4::device::Rs4Segment& segment) : segment_(segment) {
  const auto address = segment.rs4_address();
  hub_->watch(address, segment.device());
  // The PLC's side, which only the simulated bus has: the F-host's state and the input byte
  // the PLC program reads (0 while passivated) [RS4 manual §7.3.2].
  hub_->watch(std::make_unique<ItemsWatcher>(address, [&segment](dp::TimePoint) {
    char byte[3];
    std::snprintf(byte, sizeof byte, "%02x", segment.input_byte());
    return ItemsWatcher::Items{
        {"fhost-state", std::string(profisafe::to_token(segment.fhost().state()))},
        {"plc-input-byte", byte}};
  }));
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

std::string SegmentTarget::ack_rei(std::uint8_t address) {
  if (address != segment_.rs4_address()) return "no F-host for station " + std::to_string(address);
  if (!segment_.fhost().ack_req()) {
    return "the F-host is in " + std::string(profisafe::to_token(segment_.fhost().state())) +
           ", not ack-required: there is nothing to acknowledge";
  }
  segment_.ack_rei();
  hub_->poll(segment_.now());
  return {};
}

bool SegmentTarget::plc_view(std::uint8_t address, v1::PlcView& out) {
  if (address != segment_.rs4_address()) return false;
  fill_fhost(segment_.fhost(), segment_.input_byte(), out);
  out.set_data_exchange(segment_.in_data_exchange());
  if (const auto status = segment_.master().slave_status(address)) {
    fill_dp_counters(status->counters, *out.mutable_dp());
  }
  return true;
}

}  // namespace rs4sim::rpc
