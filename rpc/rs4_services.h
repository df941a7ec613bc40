#pragma once
// The rs4sim.v1 services of an RS4 run (docs/rpc.md): Device, Observation, Faults, SimTime
// (Observation's event stream and SimTime serve every run).
// Requests are checked on the gRPC thread (INVALID_ARGUMENT with the field), then run on
// the loop through the Executor; no core is touched from a gRPC thread.

#include "rpc/executor.h"
#include "rpc/rs4_target.h"
#include "rs4sim/v1/rs4.grpc.pb.h"

#include <cstdint>
#include <map>
#include <memory>
#include <vector>

namespace rs4sim::gsd {
class GsdStation;
}

namespace rs4sim::rpc {

struct Rs4Context {
  Rs4Target& target;
  Executor& executor;
  operator RunContext() const { return {target, executor}; }  // NOLINT: an RS4 run is a run
};

class DeviceService final : public v1::Device::Service {
 public:
  explicit DeviceService(Rs4Context context) : c_(context) {}
  grpc::Status ListDevices(grpc::ServerContext*, const v1::ListDevicesRequest*,
                           v1::ListDevicesResponse* out) override;
  grpc::Status AddObstacle(grpc::ServerContext*, const v1::AddObstacleRequest* in,
                           v1::AddObstacleResponse* out) override;
  grpc::Status RemoveObstacle(grpc::ServerContext*, const v1::RemoveObstacleRequest* in,
                              v1::Empty*) override;
  grpc::Status ClearScene(grpc::ServerContext*, const v1::StationRequest* in, v1::Empty*) override;
  grpc::Status ViolateField(grpc::ServerContext*, const v1::ViolateFieldRequest* in,
                            v1::AddObstacleResponse* out) override;
  grpc::Status SetContamination(grpc::ServerContext*, const v1::SetContaminationRequest* in,
                                v1::Empty*) override;
  grpc::Status InjectFault(grpc::ServerContext*, const v1::FaultRequest* in, v1::Empty*) override;
  grpc::Status ClearFault(grpc::ServerContext*, const v1::FaultRequest* in, v1::Empty*) override;
  grpc::Status SetPcAdapter(grpc::ServerContext*, const v1::SetPcAdapterRequest* in,
                            v1::Empty*) override;
  grpc::Status PressRestart(grpc::ServerContext*, const v1::PressRestartRequest* in,
                            v1::Empty*) override;
  grpc::Status SetRestartButton(grpc::ServerContext*, const v1::SetRestartButtonRequest* in,
                                v1::Empty*) override;
  grpc::Status SetPower(grpc::ServerContext*, const v1::SetPowerRequest* in, v1::Empty*) override;
  grpc::Status PowerCycle(grpc::ServerContext*, const v1::StationRequest* in, v1::Empty*) override;
  grpc::Status SetAddressSwitches(grpc::ServerContext*, const v1::SetAddressSwitchesRequest* in,
                                  v1::Empty*) override;
  grpc::Status ExchangeScanner(grpc::ServerContext*, const v1::ExchangeScannerRequest* in,
                               v1::Empty*) override;
  grpc::Status GetParameterSet(grpc::ServerContext*, const v1::StationRequest* in,
                               v1::ParameterSetDocument* out) override;
  grpc::Status SetParameterSet(grpc::ServerContext*, const v1::SetParameterSetRequest* in,
                               v1::ParameterSetDocument* out) override;

 private:
  grpc::Status fault(std::uint32_t address, v1::Fault fault, bool inject);
  Rs4Context c_;
  // Per station, the number of the restart button's last change (loop thread only; shared with
  // the release a PressRestart has scheduled, which may outlive the call).
  std::shared_ptr<std::map<std::uint8_t, std::uint64_t>> button_changes_ =
      std::make_shared<std::map<std::uint8_t, std::uint64_t>>();
};

class ObservationService final : public v1::Observation::Service {
 public:
  // A run without RS4s (a byte line's) serves the event stream only; its GetState and
  // GetContour name the device's own service.
  explicit ObservationService(RunContext context) : c_(context) {}
  [[nodiscard]] const RunContext& run() const { return c_; }  // Run.Describe's stations
  grpc::Status GetState(grpc::ServerContext*, const v1::StationRequest* in,
                        v1::DeviceState* out) override;
  grpc::Status GetContour(grpc::ServerContext*, const v1::StationRequest* in,
                          v1::Contour* out) override;
  // rpc/event_stream.cpp
  grpc::Status StreamEvents(grpc::ServerContext* context, const v1::StreamEventsRequest* in,
                            grpc::ServerWriter<v1::Event>* out) override;

 private:
  RunContext c_;
};

class FaultsService final : public v1::Faults::Service {
 public:
  explicit FaultsService(Rs4Context context) : c_(context) {}
  grpc::Status InjectBusFault(grpc::ServerContext*, const v1::BusFaultRequest* in,
                              v1::BusFaultResponse* out) override;
  grpc::Status ClearBusFaults(grpc::ServerContext*, const v1::Empty*, v1::Empty*) override;
  grpc::Status SetSilenced(grpc::ServerContext*, const v1::SetSilencedRequest* in,
                           v1::Empty*) override;
  grpc::Status InjectSafetyFault(grpc::ServerContext*, const v1::SafetyFaultRequest* in,
                                 v1::Empty*) override;
  grpc::Status AcknowledgeReintegration(grpc::ServerContext*, const v1::StationRequest* in,
                                        v1::Empty*) override;
  grpc::Status ClearSafetyFaults(grpc::ServerContext*, const v1::StationRequest* in,
                                 v1::Empty*) override;

 private:
  Rs4Context c_;
};

class SimTimeService final : public v1::SimTime::Service {
 public:
  // Reads the run's clock once, as the run's start (TimeResponse.start_ns): built before the
  // run's loop starts, on the thread that runs it.
  explicit SimTimeService(RunContext context) : c_(context), start_(context.target.now()) {}
  grpc::Status Now(grpc::ServerContext*, const v1::Empty*, v1::TimeResponse* out) override;
  grpc::Status Advance(grpc::ServerContext*, const v1::AdvanceRequest* in,
                       v1::TimeResponse* out) override;
  grpc::Status RunUntil(grpc::ServerContext*, const v1::RunUntilRequest* in,
                        v1::RunUntilResponse* out) override;

 private:
  void time(v1::TimeResponse& out) const;  // on the loop
  RunContext c_;
  dp::TimePoint start_;
};

// Device, Observation, Faults, SimTime and Diagnostics over `target`: the services of a run
// with RS4s; Diagnostics answers for the run's GSD stations `gsd` too.
std::vector<std::shared_ptr<grpc::Service>> rs4_service_set(
    Rs4Target& target, Executor& executor, const std::vector<gsd::GsdStation*>& gsd = {});

}  // namespace rs4sim::rpc
