#pragma once
// rs4sim.v1.GsdMaster (rpc/proto/rs4sim/v1/gsd.proto, docs/gsd.md "Our master with GSD
// slaves"): the GSD slaves of `rs4sim master` (gsd/station/gsd_master_slaves.h) as the master
// sees them. The harness sets the outputs the master sends, per module, and reads the inputs
// it received; for a PROFIsafe F-module, the F-host's state, its F-output data and the operator
// acknowledgement ACK_REI. Requests are checked on the gRPC thread and run on the loop through `executor`;
// `master` is called there (the master of the running MasterService).

#include "dp/master/master.h"
#include "gsd/station/gsd_master_slaves.h"
#include "rpc/executor.h"
#include "rs4sim/v1/gsd.grpc.pb.h"

#include <functional>

namespace rs4sim::rpc {

class GsdMasterService final : public v1::GsdMaster::Service {
 public:
  GsdMasterService(Executor& executor, gsd::GsdMasterSlaves& slaves,
                   std::function<dp::master::Master&()> master)
      : executor_(executor), slaves_(slaves), master_(std::move(master)) {}
  grpc::Status ListSlaves(grpc::ServerContext*, const v1::Empty*,
                          v1::ListGsdMasterSlavesResponse* out) override;
  grpc::Status GetSlave(grpc::ServerContext*, const v1::StationRequest* in,
                        v1::GsdMasterSlave* out) override;
  grpc::Status SetOutputs(grpc::ServerContext*, const v1::SetGsdOutputsRequest* in,
                          v1::Empty*) override;
  // The F-modules' F-hosts (gsd::GsdMasterFModule).
  grpc::Status SetFOutputs(grpc::ServerContext*, const v1::SetGsdOutputsRequest* in,
                           v1::Empty*) override;
  grpc::Status AcknowledgeF(grpc::ServerContext*, const v1::GsdFAcknowledgeRequest* in,
                            v1::Empty*) override;

 private:
  // Runs `act` on the loop for the F-module in `slot` of the slave at `address`; NOT_FOUND or
  // INVALID_ARGUMENT (listing what there is) when there is none. `act` may set the status.
  using FModuleAct = std::function<void(const gsd::GsdMasterSlave&, const gsd::GsdMasterFModule&,
                                        grpc::Status&)>;
  grpc::Status with_f_module(std::uint32_t address, std::uint32_t slot, const FModuleAct& act);

  Executor& executor_;
  gsd::GsdMasterSlaves& slaves_;
  std::function<dp::master::Master&()> master_;
};

}  // namespace rs4sim::rpc
