#pragma once
// rs4sim.v1.Polaris, the Optoscan Polaris service (devices.proto, docs/polaris.md, docs/rpc.md). A
// request is checked on the gRPC thread (INVALID_ARGUMENT with the field), then runs on the loop
// through the Executor; after a change the hub looks at the device at once (the core wakes
// the link itself when its deadline or queue moved).

#include "polaris/device.h"
#include "rpc/items_watcher.h"
#include "rpc/line_service_support.h"
#include "rs4sim/v1/devices.grpc.pb.h"

#include <cstdint>
#include <memory>
#include <system_error>

namespace rs4sim::rpc {

// InjectFault, ClearFault, Exchange and Receive: line::LineService.
class PolarisService final
    : public line::LineService<v1::Polaris::Service, v1::PolarisFaultRequest> {
 public:
  PolarisService(LineContext context, polaris::Device& device);
  grpc::Status GetState(grpc::ServerContext*, const v1::LineDeviceRequest* in,
                        v1::PolarisState* out) override;
  grpc::Status SetBlocked(grpc::ServerContext*, const v1::SetBlockedRequest* in,
                          v1::Empty*) override;
  grpc::Status Calibrate(grpc::ServerContext*, const v1::LineDeviceRequest* in,
                         v1::Empty*) override;
  grpc::Status SetTiming(grpc::ServerContext*, const v1::PolarisTimingRequest* in,
                         v1::Empty*) override;
  grpc::Status SetSw1(grpc::ServerContext*, const v1::PolarisSw1Request* in,
                      v1::Empty*) override;

 private:
  grpc::Status fault(const v1::PolarisFaultRequest& in, bool inject) override;
  // A refused auto-calibration start as FAILED_PRECONDITION.
  grpc::Status calibration_refused(const std::error_code& ec) const;
  polaris::Device& d_;
};

// The event-stream watcher (StateChange.what in docs/rpc.md).
std::unique_ptr<Watcher> polaris_watcher(std::uint8_t address, const polaris::Device& device);

}  // namespace rs4sim::rpc
