// rs4sim.v1.Run/Describe lists the run's stations (rpc/run_service.h): every station of the
// run its Observation service observes, by address, with its typed kind, its --device word
// and the services of the server that serve it. A real server on loopback.
#include "rpc/executor.h"
#include "rpc/rs4_services.h"
#include "rpc/run_target.h"
#include "rpc/server.h"
#include "rs4sim/v1/devices.grpc.pb.h"
#include "rs4sim/v1/run.grpc.pb.h"

#include <gtest/gtest.h>

#include <grpcpp/create_channel.h>
#include <grpcpp/security/credentials.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

namespace rs4sim::rpc {
namespace {

class InlineExecutor final : public Executor {
 public:
  void run(const std::function<void()>& f) override { f(); }
};

// A run of `kind` at `addresses`; `stations` (non-empty): what it lists instead of the default
// (a bus file's run lists several kinds, out of address order).
class FakeRun final : public RunTarget {
 public:
  FakeRun(stream::DeviceKind kind, std::vector<std::uint8_t> addresses,
          std::vector<RunStation> stations = {})
      : kind_(kind), addresses_(std::move(addresses)), stations_(std::move(stations)) {}
  [[nodiscard]] std::vector<std::uint8_t> addresses() const override { return addresses_; }
  [[nodiscard]] dp::TimePoint now() const override { return {}; }
  [[nodiscard]] bool simulated() const override { return true; }
  bool run_until(const std::function<bool()>& done, dp::Duration) override { return done(); }
  dp::link::MemoryBus* bus() override { return nullptr; }
  void after(dp::Duration, std::function<void()> f) override { f(); }
  [[nodiscard]] stream::DeviceKind kind() const override { return kind_; }
  [[nodiscard]] std::vector<RunStation> stations() const override {
    return stations_.empty() ? RunTarget::stations() : stations_;
  }

 private:
  stream::DeviceKind kind_;
  std::vector<std::uint8_t> addresses_;
  std::vector<RunStation> stations_;
};

v1::RunDescription describe(const std::vector<grpc::Service*>& services) {
  RpcServer server(ServerOptions{}, services);
  auto stub =
      v1::Run::NewStub(grpc::CreateChannel(server.address(), grpc::InsecureChannelCredentials()));
  grpc::ClientContext ctx;
  v1::RunDescription out;
  const auto status = stub->Describe(&ctx, v1::DescribeRunRequest{}, &out);
  EXPECT_TRUE(status.ok()) << status.error_message();
  server.shutdown();
  return out;
}

std::vector<std::string> list(const google::protobuf::RepeatedPtrField<std::string>& r) {
  return {r.begin(), r.end()};
}

TEST(RunDescribe, ListsEveryStationWithItsKindAndTheServicesThatServeIt) {
  FakeRun run(stream::DeviceKind::kRs4, {4},
              {{7, stream::DeviceKind::kGeneric},
               {5, stream::DeviceKind::kMetron},
               {4, stream::DeviceKind::kRs4}});
  InlineExecutor executor;
  ObservationService observation(RunContext{run, executor});
  v1::Metron::Service metron;  // the METRON's service (its calls unimplemented here)
  const auto d = describe({&observation, &metron});
  ASSERT_EQ(d.stations_size(), 3);
  EXPECT_EQ(d.stations(0).address(), 4U);
  EXPECT_EQ(d.stations(0).kind(), v1::STATION_KIND_RS4);
  EXPECT_EQ(d.stations(0).name(), "rs4");
  // Device and Faults are not served by this server: only what it serves is listed.
  EXPECT_EQ(list(d.stations(0).services()), std::vector<std::string>{"rs4sim.v1.Observation"});
  EXPECT_EQ(d.stations(1).address(), 5U);
  EXPECT_EQ(d.stations(1).kind(), v1::STATION_KIND_METRON);
  EXPECT_EQ(d.stations(1).name(), "metron");
  EXPECT_EQ(list(d.stations(1).services()),
            (std::vector<std::string>{"rs4sim.v1.Metron", "rs4sim.v1.Observation"}));
  EXPECT_EQ(d.stations(2).address(), 7U);
  EXPECT_EQ(d.stations(2).kind(), v1::STATION_KIND_GENERIC);
  EXPECT_EQ(d.stations(2).name(), "generic");
}

TEST(RunDescribe, TheDefaultStationsAreTheAddressesOfTheRunsKind) {
  FakeRun run(stream::DeviceKind::kGridScan, {0});
  InlineExecutor executor;
  ObservationService observation(RunContext{run, executor});
  const auto d = describe({&observation});
  ASSERT_EQ(d.stations_size(), 1);
  EXPECT_EQ(d.stations(0).address(), 0U);
  EXPECT_EQ(d.stations(0).kind(), v1::STATION_KIND_GRIDSCAN);
  EXPECT_EQ(d.stations(0).name(), "gridscan");
}

TEST(RunDescribe, ARunWithoutObservationListsNoStation) {
  v1::Metron::Service metron;
  const auto d = describe({&metron});
  EXPECT_EQ(d.stations_size(), 0);
  const auto services = list(d.services());
  EXPECT_NE(std::find(services.begin(), services.end(), "rs4sim.v1.Metron"), services.end());
}

}  // namespace
}  // namespace rs4sim::rpc
