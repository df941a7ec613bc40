#pragma once
// The PLC side of a simulated segment (rs4/device/rs4_segment.h) for rs4sim.v1.Plc: our master's
// output byte through the F-host and its acknowledgement mode (`run --link memory`).

#include "rpc/plc_service.h"
#include "rpc/run_target.h"
#include "rs4/device/rs4_segment.h"

namespace rs4sim::rpc {

class SegmentPlc final : public PlcTarget {
 public:
  // `segment` and `run` (whose after() times a pulse on the manual clock) outlive it.
  SegmentPlc(rs4::device::Rs4Segment& segment, RunTarget& run) : segment_(segment), run_(run) {}
  [[nodiscard]] std::vector<std::uint8_t> plc_stations() const override {
    return {segment_.rs4_address()};
  }
  [[nodiscard]] std::optional<std::uint8_t> output_byte(std::uint8_t address) const override;
  void set_output_byte(std::uint8_t address, std::uint8_t out) override;
  [[nodiscard]] bool manual_acknowledge(std::uint8_t address) const override;
  void set_manual_acknowledge(std::uint8_t address, bool manual) override;
  void after(dp::Duration delay, std::function<void()> f) override {
    run_.after(delay, std::move(f));
  }

 private:
  rs4::device::Rs4Segment& segment_;
  RunTarget& run_;
};

}  // namespace rs4sim::rpc
