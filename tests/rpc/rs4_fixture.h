#pragma once
// The fixture of the rs4sim.v1 end-to-end tests: a real gRPC server on loopback in front of a
// simulated RS4 segment (rpc/segment_target.h) whose loop runs on its own thread, as in a run.
#include "google/rpc/error_details.pb.h"
#include "google/rpc/status.pb.h"
#include "rpc/executor.h"
#include "rpc/rs4_services.h"
#include "rpc/segment_target.h"
#include "rpc/server.h"
#include "rpc_calls.h"
#include "rs4sim/v1/rs4.grpc.pb.h"
#include "test_loop.h"

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

class RpcRs4Test : public ::testing::Test, protected TestLoop {
 protected:
  void SetUp() override {
    segment_.power_on();
    start_loop();
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
    stop_loop();
  }

  bool run_until(v1::Condition condition, std::uint64_t timeout_ms) {
    v1::RunUntilRequest req;
    req.set_address(4);
    req.set_condition(condition);
    req.set_timeout_ms(timeout_ms);
    v1::RunUntilResponse res;
    const auto status = unary(*time_stub_, &v1::SimTime::Stub::RunUntil, req, res);
    EXPECT_TRUE(status.ok()) << status.error_message();
    return res.reached();
  }
  v1::DeviceState state() {
    v1::DeviceState out;
    EXPECT_TRUE(
        unary(*observation_stub_, &v1::Observation::Stub::GetState, station_request(4), out).ok());
    return out;
  }
  void advance(std::uint64_t ms) {
    v1::AdvanceRequest req;
    req.set_duration_ms(ms);
    v1::TimeResponse t;
    ASSERT_TRUE(unary(*time_stub_, &v1::SimTime::Stub::Advance, req, t).ok());
  }
  void press_restart(std::uint32_t ms) {
    v1::PressRestartRequest req;
    req.set_address(4);
    req.set_duration_ms(ms);
    ASSERT_TRUE(unary(*device_stub_, &v1::Device::Stub::PressRestart, req).ok());
  }
  // Device.ViolateField at station 4: the obstacle it added in `obstacle`.
  grpc::Status violate_field(v1::FieldKind field, v1::AddObstacleResponse& obstacle) {
    v1::ViolateFieldRequest req;
    req.set_address(4);
    req.set_field(field);
    return unary(*device_stub_, &v1::Device::Stub::ViolateField, req, obstacle);
  }
  grpc::Status set_contamination(std::uint32_t address, std::uint32_t percent) {
    v1::SetContaminationRequest req;
    req.set_address(address);
    req.set_percent(percent);
    return unary(*device_stub_, &v1::Device::Stub::SetContamination, req);
  }
  grpc::Status remove_obstacle(std::uint32_t id) {
    v1::RemoveObstacleRequest req;
    req.set_address(4);
    req.set_obstacle_id(id);
    return unary(*device_stub_, &v1::Device::Stub::RemoveObstacle, req);
  }
  grpc::Status set_restart_button(bool pressed) {
    v1::SetRestartButtonRequest req;
    req.set_address(4);
    req.set_pressed(pressed);
    return unary(*device_stub_, &v1::Device::Stub::SetRestartButton, req);
  }
  grpc::Status inject_safety_fault(v1::SafetyFault fault, std::uint32_t count) {
    v1::SafetyFaultRequest req;
    req.set_address(4);
    req.set_fault(fault);
    req.set_count(count);
    return unary(*faults_stub_, &v1::Faults::Stub::InjectSafetyFault, req);
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
  SegmentTarget target_{segment_};
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

}  // namespace rs4sim::rpc
