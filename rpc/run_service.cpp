#include "rpc/run_service.h"

#include <grpcpp/impl/server_builder_option.h>
#include <grpcpp/impl/server_builder_plugin.h>
#include <grpcpp/impl/server_initializer.h>

#include <algorithm>

namespace rs4sim::rpc {
namespace {

// A ServerBuilderPlugin is called with the server while it is built; it takes the server's
// list of service names from it.
class ServiceListPlugin final : public grpc::ServerBuilderPlugin {
 public:
  explicit ServiceListPlugin(const std::vector<std::string>*& list) : list_(list) {}
  std::string name() override { return "rs4sim.run_service_list"; }
  void InitServer(grpc::ServerInitializer* si) override { list_ = si->GetServiceList(); }
  void Finish(grpc::ServerInitializer*) override {}
  void ChangeArguments(const std::string&, void*) override {}

 private:
  const std::vector<std::string>*& list_;
};

class ServiceListOption final : public grpc::ServerBuilderOption {
 public:
  explicit ServiceListOption(const std::vector<std::string>*& list) : list_(list) {}
  void UpdateArguments(grpc::ChannelArguments*) override {}
  void UpdatePlugins(std::vector<std::unique_ptr<grpc::ServerBuilderPlugin>>* plugins) override {
    plugins->push_back(std::make_unique<ServiceListPlugin>(list_));
  }

 private:
  const std::vector<std::string>*& list_;
};

}  // namespace

std::unique_ptr<grpc::ServerBuilderOption> RunService::builder_option() {
  return std::make_unique<ServiceListOption>(services_);
}

grpc::Status RunService::Describe(grpc::ServerContext*, const v1::DescribeRunRequest*,
                                  v1::RunDescription* out) {
  std::vector<std::string> names = services_ ? *services_ : std::vector<std::string>{};
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  for (auto& name : names) out->add_services(std::move(name));
  return grpc::Status::OK;
}

}  // namespace rs4sim::rpc
