#pragma once
// rs4sim.v1.Run (run.proto, docs/rpc.md "Run"): what the run serves. rpc::RpcServer registers
// it on every server it builds and shows it the server's list of services while building
// (the way gRPC's own reflection service learns them), before any call is served.

#include "rs4sim/v1/run.grpc.pb.h"

#include <memory>
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
  grpc::Status Describe(grpc::ServerContext*, const v1::DescribeRunRequest*,
                        v1::RunDescription* out) override;

 private:
  // The server's own list (grpc::ServerInitializer::GetServiceList): complete once the server
  // serves, and alive as long as it does.
  const std::vector<std::string>* services_ = nullptr;
};

}  // namespace rs4sim::rpc
