#pragma once
// The fixture of the rs4sim.v1 end-to-end tests: a real gRPC server on loopback in front of a
// simulated RS4 segment (rpc/segment_target.h) whose loop runs on its own thread, as in a run.
#include "google/rpc/error_details.pb.h"
#include "google/rpc/status.pb.h"
#include "rpc/executor.h"
#include "rpc/rs4_services.h"
#include "rpc/segment_target.h"
#include "rpc/server.h"
#include "rs4sim/v1/rs4.grpc.pb.h"

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>
#include <gtest/gtest.h>

#include <grpcpp/create_channel.h>
#include <grpcpp/generic/generic_stub.h>
#include <grpcpp/security/credentials.h>
#include <grpcpp/support/byte_buffer.h>

#include <future>
#include <memory>
#include <optional>
#include <thread>

namespace rs4sim::rpc {

using namespace std::chrono_literals;

class RpcRs4Test : public ::testing::Test {
 protected:
  void SetUp() override {
    segment_.power_on();
    loop_ = std::thread([this] { io_.run(); });
    server_ = std::make_unique<RpcServer>(
        ServerOptions{}, std::vector<grpc::Service*>{&device_, &observation_, &time_, &faults_});
    channel_ = grpc::CreateChannel(server_->address(), grpc::InsecureChannelCredentials());
    device_stub_ = v1::Device::NewStub(channel_);
    observation_stub_ = v1::Observation::NewStub(channel_);
    time_stub_ = v1::SimTime::NewStub(channel_);
    faults_stub_ = v1::Faults::NewStub(channel_);
  }
  void TearDown() override {
    server_->shutdown();
    work_.reset();
    loop_.join();
  }

  bool run_until(v1::Condition condition, std::uint64_t timeout_ms) {
    grpc::ClientContext ctx;
    v1::RunUntilRequest req;
    req.set_address(4);
    req.set_condition(condition);
    req.set_timeout_ms(timeout_ms);
    v1::RunUntilResponse res;
    const auto status = time_stub_->RunUntil(&ctx, req, &res);
    EXPECT_TRUE(status.ok()) << status.error_message();
    return res.reached();
  }
  v1::DeviceState state() {
    grpc::ClientContext ctx;
    v1::StationRequest req;
    req.set_address(4);
    v1::DeviceState out;
    EXPECT_TRUE(observation_stub_->GetState(&ctx, req, &out).ok());
    return out;
  }
  void advance(std::uint64_t ms) {
    grpc::ClientContext ctx;
    v1::AdvanceRequest req;
    req.set_duration_ms(ms);
    v1::TimeResponse t;
    ASSERT_TRUE(time_stub_->Advance(&ctx, req, &t).ok());
  }
  void press_restart(std::uint32_t ms) {
    grpc::ClientContext ctx;
    v1::PressRestartRequest req;
    req.set_address(4);
    req.set_duration_ms(ms);
    v1::Empty e;
    ASSERT_TRUE(device_stub_->PressRestart(&ctx, req, &e).ok());
  }
  // Power-up with the factory start/restart interlock: the OSSD waits for a restart pulse
  // once the RS4 measures [RS4 manual §4.3].
  void boot() {
    ASSERT_TRUE(run_until(v1::CONDITION_DATA_EXCHANGE, 10'000));
    ASSERT_TRUE(run_until(v1::CONDITION_RS4_MEASURING, 60'000));
    ASSERT_FALSE(run_until(v1::CONDITION_OSSD_ON, 500));
    press_restart(200);
    ASSERT_TRUE(run_until(v1::CONDITION_OSSD_ON, 1000));
  }

  rs4::device::Rs4Segment segment_{rs4::device::Rs4SegmentConfig{}};
  boost::asio::io_context io_;
  std::optional<boost::asio::executor_work_guard<boost::asio::io_context::executor_type>> work_{
      io_.get_executor()};
  std::thread loop_;
  SegmentTarget target_{segment_};
  AsioExecutor executor_{io_};
  DeviceService device_{{target_, executor_}};
  ObservationService observation_{{target_, executor_}};
  SimTimeService time_{{target_, executor_}};
  FaultsService faults_{{target_, executor_}};
  std::unique_ptr<RpcServer> server_;
  std::shared_ptr<grpc::Channel> channel_;
  std::unique_ptr<v1::Device::Stub> device_stub_;
  std::unique_ptr<v1::Observation::Stub> observation_stub_;
  std::unique_ptr<v1::SimTime::Stub> time_stub_;
  std::unique_ptr<v1::Faults::Stub> faults_stub_;
};

// The BadRequest field of an INVALID_ARGUMENT status.
inline std::string bad_field(const grpc::Status& status) {
  google::rpc::Status rich;
  if (!rich.ParseFromString(status.error_details()) || rich.details_size() != 1) return "?";
  google::rpc::BadRequest bad;
  if (!rich.details(0).UnpackTo(&bad) || bad.field_violations_size() != 1) return "?";
  return bad.field_violations(0).field();
}

}  // namespace rs4sim::rpc
