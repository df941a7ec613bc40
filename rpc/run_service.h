#pragma once
// rs4sim.v1.Run (run.proto, docs/rpc.md "Run"): what the run serves. rpc::RpcServer registers
// it on every server it builds and shows it the server's list of services while building
// (the way gRPC's own reflection service learns them), before any call is served. The
// stations come from the run the server's Observation service observes (RunTarget::stations,
// on the loop), each with the services of the server that serve its kind.

#include "rpc/run_target.h"
#include "rs4sim/v1/run.grpc.pb.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace grpc {
class ServerBuilderOption;
}

namespace rs4sim::rpc {

class RunService final : public v1::Run::Service {
 public:
  // The option that shows this service its server's list of services; add it to the
  // ServerBuilder that registers this service. The service must outlive the server.
  std::unique_ptr<grpc::ServerBuilderOption> builder_option();
  // The server's services: the run of its Observation service (rpc::ObservationService) is
  // the one whose stations Describe lists; none (`master`): no stations.
  void observe(const std::vector<grpc::Service*>& services);
  grpc::Status Describe(grpc::ServerContext*, const v1::DescribeRunRequest*,
                        v1::RunDescription* out) override;

 private:
  // The server's own list (grpc::ServerInitializer::GetServiceList): complete once the server
  // serves, and alive as long as it does.
  const std::vector<std::string>* services_ = nullptr;
  std::optional<RunContext> run_;
};

}  // namespace rs4sim::rpc
