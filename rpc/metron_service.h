#pragma once
// rs4sim.v1.Metron, the ReeR METRON service (devices.proto, docs/metron.md, docs/rpc.md). A request
// is checked on the gRPC thread (INVALID_ARGUMENT with the field), then runs on the loop
// through the Executor; after a change the hub looks at the device at once (the core wakes
// the link itself when its deadline or queue moved).

#include "metron/device.h"
#include "rpc/items_watcher.h"
#include "rpc/line_service_support.h"
#include "rs4sim/v1/devices.grpc.pb.h"

#include <cstdint>
#include <memory>

namespace rs4sim::rpc {

// InjectFault, ClearFault, Exchange and Receive: line::LineService.
class MetronService final : public line::LineService<v1::Metron::Service, v1::MetronFaultRequest> {
 public:
  MetronService(LineContext context, metron::Device& device);
  grpc::Status GetState(grpc::ServerContext*, const v1::LineDeviceRequest* in,
                        v1::MetronState* out) override;
  grpc::Status SetBlocked(grpc::ServerContext*, const v1::SetBlockedRequest* in,
                          v1::Empty*) override;
  grpc::Status SetSynchronised(grpc::ServerContext*, const v1::SetSynchronisedRequest* in,
                               v1::Empty*) override;
  grpc::Status SetInput(grpc::ServerContext*, const v1::SetInputRequest* in, v1::Empty*) override;
  grpc::Status SetTiming(grpc::ServerContext*, const v1::MetronTimingRequest* in,
                         v1::Empty*) override;

 private:
  grpc::Status fault(const v1::MetronFaultRequest& in, bool inject) override;
  metron::Device& d_;
};

// The event-stream watcher (StateChange.what in docs/rpc.md).
std::unique_ptr<Watcher> metron_watcher(std::uint8_t address, const metron::Device& device);

}  // namespace rs4sim::rpc
