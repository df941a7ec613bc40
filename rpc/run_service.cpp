#include "rpc/run_service.h"

#include "rpc/executor.h"
#include "rpc/line_devices.h"
#include "rpc/rs4_services.h"
#include "rs4sim/v1/gsd.grpc.pb.h"
#include "rs4sim/v1/proxy_service.grpc.pb.h"
#include "rs4sim/v1/rs4.grpc.pb.h"

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

// The services that serve a station of `kind` (those the server serves are listed); a line
// device's: its own (rpc/line_devices.h) and Observation.
std::vector<std::string> services_of(stream::DeviceKind kind) {
  const std::string observation = v1::Observation::service_full_name();
  switch (kind) {
    case stream::DeviceKind::kRs4:
      return {v1::Device::service_full_name(), v1::Faults::service_full_name(), observation,
              v1::Proxy::service_full_name()};
    case stream::DeviceKind::kGeneric: return {v1::GsdStations::service_full_name(), observation};
    case stream::DeviceKind::kEcho: return {};
    default: break;  // a line device (RS4SIM_LINE_DEVICES)
  }
  if (const auto* line = find_line_api(kind)) return {line->service, observation};
  return {};
}

void add_station(const RunStation& s, const std::vector<std::string>& served,
                 v1::RunDescription& out) {
  auto* station = out.add_stations();
  station->set_address(s.address);
  // The enum's numbers are DeviceKind's (run.proto).
  station->set_kind(static_cast<v1::StationKind>(s.kind));
  station->set_name(std::string(stream::to_string(s.kind)));
  auto services = services_of(s.kind);
  std::sort(services.begin(), services.end());
  for (auto& name : services) {
    if (std::binary_search(served.begin(), served.end(), name)) station->add_services(name);
  }
}

}  // namespace

void RunService::observe(const std::vector<grpc::Service*>& services) {
  for (auto* s : services) {
    if (const auto* observation = dynamic_cast<const ObservationService*>(s)) {
      run_.emplace(observation->run());
      return;
    }
  }
}

std::unique_ptr<grpc::ServerBuilderOption> RunService::builder_option() {
  return std::make_unique<ServiceListOption>(services_);
}

grpc::Status RunService::Describe(grpc::ServerContext*, const v1::DescribeRunRequest*,
                                  v1::RunDescription* out) {
  std::vector<std::string> names = services_ ? *services_ : std::vector<std::string>{};
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  for (const auto& name : names) out->add_services(name);
  if (!run_) return grpc::Status::OK;
  std::vector<RunStation> stations;
  run_->executor.run([&] { stations = run_->target.stations(); });
  std::sort(stations.begin(), stations.end(),
            [](const RunStation& a, const RunStation& b) { return a.address < b.address; });
  for (const auto& s : stations) add_station(s, names, *out);
  return grpc::Status::OK;
}

}  // namespace rs4sim::rpc
