#pragma once
// rs4sim.v1.BusMaster (docs/http.md "Station counters"): what `rs4sim master`'s own class 1
// master and F-hosts know of each RS4 they poll, read on the loop through the Executor.

#include "dp/time/clock.h"
#include "rpc/executor.h"
#include "rs4/device/rs4_master_station.h"
#include "rs4sim/v1/rs4.grpc.pb.h"

namespace rs4sim::rpc {

// One station's entry from the master side's views (the loop thread only).
void fill_bus_station(const rs4::device::Rs4MasterStation& station, std::uint8_t address,
                      v1::BusStation& out);

class BusMasterService final : public v1::BusMaster::Service {
 public:
  // `station` and `clock` outlive the service (the run's MasterService).
  BusMasterService(const rs4::device::Rs4MasterStation& station, const dp::Clock& clock,
                   Executor& executor)
      : station_(station), clock_(clock), executor_(executor) {}
  grpc::Status ListStations(grpc::ServerContext*, const v1::Empty*,
                            v1::BusStationsResponse* out) override;

 private:
  const rs4::device::Rs4MasterStation& station_;
  const dp::Clock& clock_;
  Executor& executor_;
};

}  // namespace rs4sim::rpc
