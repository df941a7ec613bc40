#pragma once
// rs4sim.v1.GridScan, the CEDES GridScan/Pro SI service (devices.proto, docs/gridscan.md,
// docs/rpc.md). A request is checked on the gRPC thread (INVALID_ARGUMENT with the field), then
// runs on the loop through the Executor; after a change the hub looks at the device at once (the
// core wakes the link itself when its deadline or queue moved).

#include "gridscan/device.h"
#include "rpc/items_watcher.h"
#include "rpc/line_service_support.h"
#include "rs4sim/v1/devices.grpc.pb.h"

#include <cstdint>
#include <memory>

namespace rs4sim::rpc {

// InjectFault, ClearFault, Exchange and Receive: line::LineService.
class GridScanService final
    : public line::LineService<v1::GridScan::Service, v1::GridScanFaultRequest> {
 public:
  GridScanService(LineContext context, gridscan::Device& device);
  grpc::Status GetState(grpc::ServerContext*, const v1::LineDeviceRequest* in,
                        v1::GridScanState* out) override;
  grpc::Status SetDoor(grpc::ServerContext*, const v1::SetDoorRequest* in, v1::Empty*) override;
  grpc::Status SetBlocked(grpc::ServerContext*, const v1::SetBlockedRequest* in,
                          v1::Empty*) override;
  grpc::Status SetTiming(grpc::ServerContext*, const v1::GridScanTimingRequest* in,
                         v1::Empty*) override;
  grpc::Status SetSoiling(grpc::ServerContext*, const v1::SetSoilingRequest* in,
                          v1::Empty*) override;
  grpc::Status PowerCycle(grpc::ServerContext*, const v1::PowerCycleRequest* in,
                          v1::Empty*) override;
  grpc::Status SetPower(grpc::ServerContext*, const v1::SetPowerRequest* in, v1::Empty*) override;

 private:
  grpc::Status fault(const v1::GridScanFaultRequest& in, bool inject) override;
  gridscan::Device& d_;
};

// The event-stream watcher (StateChange.what in docs/rpc.md).
std::unique_ptr<Watcher> gridscan_watcher(std::uint8_t address, const gridscan::Device& device);

}  // namespace rs4sim::rpc
