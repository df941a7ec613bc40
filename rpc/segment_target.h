#pragma once
// Rs4Target over a simulated segment (rs4/device/rs4_segment.h): one RS4, our master and
// F-host on the memory bus, on the manual clock. Time moves only through run_until/after
// (SimTime RPCs), so a harness runs the RS4's 30 s boot in milliseconds. Events: a bus
// observer gives the hub every telegram and polls the device after each.

#include "rpc/event_hub.h"
#include "rpc/rs4_target.h"
#include "rpc/segment_plc.h"
#include "rs4/device/rs4_segment.h"

namespace rs4sim::rpc {

class SegmentTarget final : public Rs4Target {
 public:
  explicit SegmentTarget(rs4::device::Rs4Segment& segment);
  [[nodiscard]] std::vector<std::uint8_t> addresses() const override;
  rs4::device::Rs4Device* device(std::uint8_t address) override;
  [[nodiscard]] dp::TimePoint now() const override { return segment_.now(); }
  [[nodiscard]] bool simulated() const override { return true; }
  bool run_until(const std::function<bool()>& done, dp::Duration limit) override;
  void after(dp::Duration delay, std::function<void()> f) override;
  dp::link::MemoryBus* bus() override { return &segment_.bus(); }
  EventHub* events() override { return hub_.get(); }
  bool plc_view(std::uint8_t address, v1::PlcView& out) override;
  std::string ack_rei(std::uint8_t address) override;
  PlcTarget* plc() override { return &plc_; }

 private:
  rs4::device::Rs4Segment& segment_;
  std::shared_ptr<EventHub> hub_ = std::make_shared<EventHub>();  // shared with the observer
  SegmentPlc plc_{segment_, *this};
};

}  // namespace rs4sim::rpc
