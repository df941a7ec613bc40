#pragma once
// The PLC side of `rs4sim master` (rs4/device/rs4_master_station.h) for rs4sim.v1.Plc: each RS4's
// output byte through its F-host, the acknowledgement mode, and `--restart-pulse`: the restart
// bit pulsed once per start-up, when the RS4 waits in its start interlock [RS4 manual §5.1.2].
// Time comes from the master's cycles (on_cycle): a pulse ends at the first cycle after its
// end, so its length is rounded up to the master's cycle (--cycle, 10 ms by default).

#include "rpc/plc_service.h"
#include "rs4/device/rs4_master_station.h"

#include <optional>
#include <set>
#include <vector>

namespace rs4sim::rpc {

class MasterPlc final : public PlcTarget {
 public:
  // `restart_pulse`: pulse the restart bit for that long once per start-up of each RS4
  // (nullopt: never by itself).
  explicit MasterPlc(std::optional<dp::Duration> restart_pulse) : restart_pulse_(restart_pulse) {}
  // The master side it writes to, once the run has started it (it outlives this); before,
  // there are no stations.
  void attach(rs4::device::Rs4MasterStation& station) { station_ = &station; }
  [[nodiscard]] std::vector<std::uint8_t> plc_stations() const override {
    return station_ != nullptr ? station_->slave_addresses() : std::vector<std::uint8_t>{};
  }
  [[nodiscard]] std::optional<std::uint8_t> output_byte(std::uint8_t address) const override;
  void set_output_byte(std::uint8_t address, std::uint8_t out) override {
    if (station_ != nullptr) station_->set_output_byte(address, out);
  }
  [[nodiscard]] bool manual_acknowledge(std::uint8_t address) const override;
  void set_manual_acknowledge(std::uint8_t address, bool manual) override;
  void after(dp::Duration delay, std::function<void()> f) override {
    due_.push_back({now_ + delay, std::move(f)});
  }
  // Every master cycle (Rs4MasterEvent MasterCycle): what is due, and the start-up pulses.
  void on_cycle(dp::TimePoint now);

 private:
  // An RS4 in data exchange, its F-host running, operational, no error, no protective field
  // violated and OSSD 0: it waits for the reset signal of its start interlock.
  [[nodiscard]] static bool in_start_interlock(const rs4::device::Rs4SlaveView& v);
  void pulse(std::uint8_t address, dp::Duration length);

  struct Due {
    dp::TimePoint at;
    std::function<void()> f;
  };
  rs4::device::Rs4MasterStation* station_ = nullptr;
  std::optional<dp::Duration> restart_pulse_;
  dp::TimePoint now_{};
  std::vector<Due> due_;
  std::set<std::uint8_t> pulsed_;  // pulsed since entering data exchange
};

}  // namespace rs4sim::rpc
