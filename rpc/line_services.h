#pragma once
// The rs4sim.v1 services of the RS-485 devices (devices.proto, docs/rpc.md): GridScan, Metron,
// Polaris. As with the RS4's, a request is checked on the gRPC thread (INVALID_ARGUMENT with
// the field), then runs on the loop through the Executor; after a change the hub looks at the
// device at once (the core wakes the link itself when its deadline or queue moved).

#include "dp/time/clock.h"
#include "gridscan/device.h"
#include "metron/metron_device.h"
#include "polaris/device.h"
#include "rpc/event_hub.h"
#include "rpc/executor.h"
#include "rpc/items_watcher.h"
#include "rpc/line_target.h"
#include "rpc/tapped_byte_device.h"
#include "rs4sim/v1/devices.grpc.pb.h"

#include <cstdint>
#include <functional>
#include <memory>

namespace rs4sim::rpc {

// What every call needs: the run's loop and clock, the device's address on its line, its
// tap, the run's event hub (nullptr: none) and, on the simulated clock, its line (nullptr on
// a real-time link: Exchange, Receive and a timed PowerCycle answer FAILED_PRECONDITION).
struct LineContext {
  Executor& executor;
  const dp::Clock& clock;
  std::uint8_t address;
  TappedByteDevice& tap;
  EventHub* hub = nullptr;
  SimulatedLine* line = nullptr;
};

class GridScanService final : public v1::GridScan::Service {
 public:
  GridScanService(LineContext context, gridscan::GridScanDevice& device)
      : c_(context), d_(device) {}
  grpc::Status GetState(grpc::ServerContext*, const v1::LineDeviceRequest* in,
                        v1::GridScanState* out) override;
  grpc::Status SetDoor(grpc::ServerContext*, const v1::SetDoorRequest* in, v1::Empty*) override;
  grpc::Status SetBlocked(grpc::ServerContext*, const v1::SetBlockedRequest* in,
                          v1::Empty*) override;
  grpc::Status SetSoiling(grpc::ServerContext*, const v1::SetSoilingRequest* in,
                          v1::Empty*) override;
  grpc::Status InjectFault(grpc::ServerContext*, const v1::GridScanFaultRequest* in,
                           v1::Empty*) override;
  grpc::Status ClearFault(grpc::ServerContext*, const v1::GridScanFaultRequest* in,
                          v1::Empty*) override;
  grpc::Status PowerCycle(grpc::ServerContext*, const v1::PowerCycleRequest* in,
                          v1::Empty*) override;
  grpc::Status SetPower(grpc::ServerContext*, const v1::SetPowerRequest* in, v1::Empty*) override;
  grpc::Status Exchange(grpc::ServerContext*, const v1::ExchangeRequest* in,
                        v1::ExchangeResponse* out) override;
  grpc::Status Receive(grpc::ServerContext*, const v1::ReceiveRequest* in,
                       v1::ReceiveResponse* out) override;

 private:
  grpc::Status fault(const v1::GridScanFaultRequest& in, bool inject);
  LineContext c_;
  gridscan::GridScanDevice& d_;
};

class MetronService final : public v1::Metron::Service {
 public:
  MetronService(LineContext context, metron::MetronDevice& device) : c_(context), d_(device) {}
  grpc::Status GetState(grpc::ServerContext*, const v1::LineDeviceRequest* in,
                        v1::MetronState* out) override;
  grpc::Status SetBlocked(grpc::ServerContext*, const v1::SetBlockedRequest* in,
                          v1::Empty*) override;
  grpc::Status SetSynchronised(grpc::ServerContext*, const v1::SetSynchronisedRequest* in,
                               v1::Empty*) override;
  grpc::Status SetInput(grpc::ServerContext*, const v1::SetInputRequest* in, v1::Empty*) override;
  grpc::Status InjectFault(grpc::ServerContext*, const v1::MetronFaultRequest* in,
                           v1::Empty*) override;
  grpc::Status ClearFault(grpc::ServerContext*, const v1::MetronFaultRequest* in,
                          v1::Empty*) override;
  grpc::Status Exchange(grpc::ServerContext*, const v1::ExchangeRequest* in,
                        v1::ExchangeResponse* out) override;
  grpc::Status Receive(grpc::ServerContext*, const v1::ReceiveRequest* in,
                       v1::ReceiveResponse* out) override;

 private:
  grpc::Status fault(const v1::MetronFaultRequest& in, bool inject);
  LineContext c_;
  metron::MetronDevice& d_;
};

class PolarisService final : public v1::Polaris::Service {
 public:
  PolarisService(LineContext context, polaris::Device& device) : c_(context), d_(device) {}
  grpc::Status GetState(grpc::ServerContext*, const v1::LineDeviceRequest* in,
                        v1::PolarisState* out) override;
  grpc::Status SetBlocked(grpc::ServerContext*, const v1::SetBlockedRequest* in,
                          v1::Empty*) override;
  grpc::Status InjectFault(grpc::ServerContext*, const v1::PolarisFaultRequest* in,
                           v1::Empty*) override;
  grpc::Status ClearFault(grpc::ServerContext*, const v1::PolarisFaultRequest* in,
                          v1::Empty*) override;
  grpc::Status Exchange(grpc::ServerContext*, const v1::ExchangeRequest* in,
                        v1::ExchangeResponse* out) override;
  grpc::Status Receive(grpc::ServerContext*, const v1::ReceiveRequest* in,
                       v1::ReceiveResponse* out) override;

 private:
  grpc::Status fault(const v1::PolarisFaultRequest& in, bool inject);
  LineContext c_;
  polaris::Device& d_;
};

// The event-stream watchers of the three devices (StateChange.what in docs/rpc.md).
std::unique_ptr<Watcher> gridscan_watcher(std::uint8_t address,
                                          const gridscan::GridScanDevice& device);
std::unique_ptr<Watcher> metron_watcher(std::uint8_t address, const metron::MetronDevice& device);
std::unique_ptr<Watcher> polaris_watcher(std::uint8_t address, const polaris::Device& device);

}  // namespace rs4sim::rpc
