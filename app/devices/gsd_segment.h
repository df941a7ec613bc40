#pragma once
// GSD stations with our class 1 master on the in-memory bus (simulated time): the master is
// configured from the same GSDs (gsd_master_entry), at the run's rate, with the largest MaxTsdr
// the GSDs declare for it. `rs4sim run --device generic --gsd FILE --link memory` and
// `rs4sim run --bus FILE --link memory`; with `--grpc` the harness drives it: GsdStations for
// every station, SimTime moving this segment's manual clock, Observation's event stream
// (docs/gsd.md "Harness API"). A station's PROFIsafe F-modules get an F-host of our master each
// (gsd::GsdMasterSlaves, as `rs4sim master` has them), run after every master cycle; it sends the
// GSD's default F-parameters (the station's --f-dest-add is the device's switch, not the
// master's knowledge) and waits for GsdStations.AckFHost after a passivation.

#include "app/devices/device_registry.h"
#include "app/devices/gsd_station_file.h"
#include "app/devices/memory_bus_target.h"
#include "dp/link/memory_bus.h"
#include "dp/master/master.h"
#include "dp/time/clock.h"
#include "gsd/station/gsd_master_slaves.h"

#include <memory>
#include <vector>

namespace rs4sim::app {

class GsdSegment final : public SimulatedSegment {
 public:
  // Throws UsageError for a rate a GSD does not support; std::system_error for a
  // configuration dp/ refuses.
  GsdSegment(std::vector<GsdStationSpec> specs, const std::string& baud,
             dp::Duration cycle_target = std::chrono::milliseconds(10));

  void run_for(dp::Duration d) override;
  [[nodiscard]] std::uint8_t master_address() const override { return master_address_; }
  void print_summary(std::ostream& out) const override;
  [[nodiscard]] bool healthy() const override;
  dp::link::MemoryBus* bus() override { return bus_.get(); }
  // GsdStations (with the bus faults), SimTime and Observation, on this segment's clock. The
  // segment must outlive the server that serves them (run_memory_served keeps it so).
  ServiceList services(const ServiceContext& context) override;
  ~GsdSegment() override;

  [[nodiscard]] dp::ManualClock& clock() { return clock_; }
  [[nodiscard]] dp::master::Master& master() { return *master_; }
  [[nodiscard]] std::vector<std::unique_ptr<GsdStation>>& stations() { return stations_; }
  [[nodiscard]] gsd::GsdMasterSlaves& f_hosts() { return *f_hosts_; }
  // Stations the master has in data exchange.
  [[nodiscard]] std::size_t in_data_exchange() const;

 private:

  dp::ManualClock clock_;
  std::uint8_t master_address_ = 1;
  std::unique_ptr<dp::link::MemoryBus> bus_;
  std::unique_ptr<dp::master::Master> master_;
  std::vector<std::unique_ptr<GsdStation>> stations_;
  std::vector<dp::master::MasterEvent> events_;
  // Our master's F-host for every F-module of the stations (docs/profisafe.md "GSD F-devices").
  std::unique_ptr<gsd::GsdMasterSlaves> f_hosts_;
  // The master's events since the last call: after each cycle the F-hosts' turn.
  void drain();
  std::unique_ptr<MemoryBusTarget> target_;  // made by services()
};

// Our master waits for the slowest responder a GSD declares: when `max_tsdr` (Tbit) is above
// the bus parameters' max TSDR, max TSDR and TID2 become it and the slot time grows by the same
// amount, keeping the margin of the [IEC 61158-4-3 bus parameters, timing] default table.
void fit_max_tsdr(dp::master::BusParameters& bus, std::uint16_t max_tsdr);

// The master's address on a segment: 1, or the lowest address no station has.
std::uint8_t free_master_address(const std::vector<std::uint8_t>& stations);

}  // namespace rs4sim::app
