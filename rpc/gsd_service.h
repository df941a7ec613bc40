#pragma once
// rs4sim.v1.GsdStations (rpc/proto/rs4sim/v1/gsd.proto, docs/gsd.md "Harness API"): the GSD
// stations of a run driven from a harness. As with the other services a request is checked on
// the gRPC thread (INVALID_ARGUMENT with the field), then runs on the loop through the
// Executor; after a change `changed` runs there (the event hub looks at once).

#include "dp/link/memory_bus.h"
#include "dp/link/turnaround.h"
#include "gsd/station/gsd_master_slaves.h"
#include "gsd/station/gsd_station.h"
#include "rpc/device_watcher.h"
#include "rpc/executor.h"
#include "rs4sim/v1/gsd.grpc.pb.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace rs4sim::rpc {

struct GsdServiceContext {
  Executor& executor;
  std::vector<gsd::GsdStation*> stations;  // distinct addresses
  // On the loop after a call changed a station (nullptr-safe: empty = nothing).
  std::function<void()> changed = {};
  // The simulated bus (--link memory) for bus faults; nullptr on a real link.
  dp::link::MemoryBus* bus = nullptr;
  // On a real-time link: the replies' turnaround of the station at an address (nullptr: none),
  // read on the loop, and --tsl (ServiceContext's); empty on the simulated bus.
  dp::link::TurnaroundSource turnaround = {};
  std::optional<std::int64_t> slot_time_us = std::nullopt;
  // The simulated bus: our master's F-hosts of the stations' F-modules (nullptr: none).
  gsd::GsdMasterSlaves* f_hosts = nullptr;
};

class GsdStationsService final : public v1::GsdStations::Service {
 public:
  explicit GsdStationsService(GsdServiceContext context) : c_(std::move(context)) {}
  grpc::Status ListStations(grpc::ServerContext*, const v1::Empty*,
                            v1::ListGsdStationsResponse* out) override;
  grpc::Status GetStation(grpc::ServerContext*, const v1::StationRequest* in,
                          v1::GsdStation* out) override;
  grpc::Status SetInputs(grpc::ServerContext*, const v1::SetGsdInputsRequest* in,
                         v1::Empty*) override;
  grpc::Status SetDiagnosis(grpc::ServerContext*, const v1::SetGsdDiagnosisRequest* in,
                            v1::Empty*) override;
  grpc::Status RaiseAlarm(grpc::ServerContext*, const v1::RaiseGsdAlarmRequest* in,
                          v1::Empty*) override;
  grpc::Status SetOnline(grpc::ServerContext*, const v1::SetGsdOnlineRequest* in,
                         v1::Empty*) override;
  grpc::Status InjectBusFault(grpc::ServerContext*, const v1::BusFaultRequest* in,
                              v1::BusFaultResponse* out) override;
  grpc::Status ClearBusFaults(grpc::ServerContext*, const v1::Empty*, v1::Empty*) override;
  // The F-modules (gsd_fdevice.proto).
  grpc::Status GetFModules(grpc::ServerContext*, const v1::StationRequest* in,
                           v1::GsdFModules* out) override;
  grpc::Status SetFInputs(grpc::ServerContext*, const v1::SetGsdInputsRequest* in,
                          v1::Empty*) override;
  grpc::Status InjectFFault(grpc::ServerContext*, const v1::InjectGsdFFaultRequest* in,
                            v1::Empty*) override;
  grpc::Status ClearFFaults(grpc::ServerContext*, const v1::GsdFModuleRequest* in,
                            v1::Empty*) override;
  grpc::Status SetFOutputs(grpc::ServerContext*, const v1::SetGsdOutputsRequest* in,
                           v1::Empty*) override;
  grpc::Status AckFHost(grpc::ServerContext*, const v1::GsdFModuleRequest* in,
                        v1::Empty*) override;

 private:
  using StationFn = std::function<grpc::Status(gsd::GsdStation&)>;
  grpc::Status on_station(std::uint32_t address, const StationFn& fn, bool changes);
  // on_station for a call that cannot fail once the station is found.
  grpc::Status with_station(std::uint32_t address, bool changes,
                            const std::function<void(gsd::GsdStation&)>& fn);
  // on_station for the F-device in `slot` (INVALID_ARGUMENT naming "slot" when there is none).
  using FModuleFn = std::function<grpc::Status(gsd::GsdStation&, gsd::FModuleDevice&)>;
  grpc::Status on_f_module(std::uint32_t address, std::uint32_t slot, const FModuleFn& fn);
  // on_f_module for our master's F-host of that F-device (FAILED_PRECONDITION off the
  // simulated bus).
  using FHostFn = std::function<grpc::Status(gsd::GsdStation&, gsd::FModuleDevice&,
                                             const gsd::GsdMasterFModule&)>;
  grpc::Status on_f_host(std::uint32_t address, std::uint32_t slot, const FHostFn& fn);
  GsdServiceContext c_;
};

// The event-stream watcher of a station (StateChange.what: "dp-state", "online", "inputs",
// "outputs", "ext-diag", "diagnosis"; the bytes in hex; "diagnosis-text": the GSD's Unit_Diag
// texts for it, "; "-separated). Per F-module: "fdevice-state" (GsdFModule.state),
// "fdevice-diagnosis" ("64: <its text>", "" for none), "f-inputs" (what it reports) and
// "f-outputs" (what it delivers of the host's), in hex; with two F-modules or more each name
// ends in ":<slot>".
std::unique_ptr<Watcher> gsd_watcher(const gsd::GsdStation& station);
// Our master's F-hosts of the station's F-modules (the simulated bus): "fhost-state"
// (GsdFHostView.state), named as above.
std::unique_ptr<Watcher> gsd_fhost_watcher(const gsd::GsdStation& station,
                                           const gsd::GsdMasterSlaves& hosts);

}  // namespace rs4sim::rpc
