// The rs4sim.v1 API on a real gRPC server on loopback, in front of a simulated RS4 segment
// (rpc/segment_target.h) whose loop runs on its own thread, as in a run. Known answers: the
// RS4 manual's behaviour (boot ≈30 s, OSSD off on a protective-field violation, restart
// interlock) and the public wire formats of grpc.health.v1 (HealthCheckResponse{status =
// SERVING} = 08 01) and google.rpc.Status/BadRequest.
#include "rs4_fixture.h"
#include "rs4sim/v1/run.grpc.pb.h"

#include <grpcpp/generic/generic_stub.h>
#include <grpcpp/support/byte_buffer.h>

#include <algorithm>
#include <future>
#include <string>
#include <vector>

namespace rs4sim::rpc {
namespace {

TEST_F(RpcRs4Test, ListensOnLoopbackOnly) {
  EXPECT_EQ(server_->address().rfind("127.0.0.1:", 0), 0U) << server_->address();
  EXPECT_GT(server_->port(), 0);
  EXPECT_NE(check_listen_address("0.0.0.0:50051").find("TLS"), std::string::npos);
  EXPECT_NE(check_listen_address("localhost").find("HOST:PORT"), std::string::npos);
  EXPECT_EQ(check_listen_address("[::1]:0"), "");
  EXPECT_THROW(RpcServer(ServerOptions{"192.168.1.2:50051"}, {}), std::invalid_argument);
}

TEST_F(RpcRs4Test, BootsInSimulatedTimeAndReportsTheState) {
  boot();
  const auto s = state();
  EXPECT_TRUE(s.powered());
  EXPECT_TRUE(s.connected());
  EXPECT_EQ(s.rs4_state(), "measuring");
  EXPECT_EQ(s.led(), "off-connected");  // [RS4 manual §4.4]: LED off in data exchange
  EXPECT_TRUE(s.input().ossd());
  EXPECT_TRUE(s.ossd());
  EXPECT_EQ(s.input_byte() & 0x80U, 0x80U);
  EXPECT_EQ(s.f_dest_add(), 504U);  // 500 + address 4 [RS4 manual §6.2]
  EXPECT_EQ(s.output().field_pair(), 1U);
  EXPECT_EQ(s.input_pdu().size(), 5U);
  EXPECT_GE(s.now_ns(), 30'000'000'000);  // the RS4 boots in ≈30 s [RS4 manual §7.1.1]
  grpc::ClientContext ctx;
  v1::TimeResponse now;
  ASSERT_TRUE(time_stub_->Now(&ctx, v1::Empty{}, &now).ok());
  EXPECT_TRUE(now.simulated());
}

TEST_F(RpcRs4Test, ProtectiveFieldViolationAndRestart) {
  boot();
  v1::AddObstacleResponse obstacle;
  ASSERT_TRUE(violate_field(v1::FIELD_KIND_PROTECTIVE, obstacle).ok());
  ASSERT_TRUE(run_until(v1::CONDITION_OSSD_OFF, 1000));
  EXPECT_TRUE(state().input().protective_field_violated());
  ASSERT_TRUE(remove_obstacle(obstacle.obstacle_id()).ok());
  // Restart interlock: the field is free, but the OSSD stays off until a restart pulse.
  EXPECT_FALSE(run_until(v1::CONDITION_OSSD_ON, 1000));
  press_restart(300);
  EXPECT_TRUE(run_until(v1::CONDITION_OSSD_ON, 1000));
}

// The scanner's own LEDs in DeviceState: LED5 yellow blinking from the contamination warning on
// [RS4 manual §8.3] (50 %, not 49 %); LED3 red while the restart button is held [RS4 manual §4.3]
// (PressRestart runs its whole pulse within the call on the simulated segment, so LED3 is dark
// again afterwards; SetRestartButton holds it, see RestartButtonHeldAndReleased).
TEST_F(RpcRs4Test, TheScannersLedsAreInTheState) {
  boot();
  EXPECT_FALSE(state().led3_red());
  EXPECT_FALSE(state().led5_yellow_blinking());
  press_restart(300);
  EXPECT_FALSE(state().led3_red()) << "released again";
  EXPECT_FALSE(state().restart_button_held());
  const auto contaminate = [&](std::uint32_t percent) {
    ASSERT_TRUE(set_contamination(4, percent).ok());
    advance(40);
  };
  contaminate(49);
  EXPECT_FALSE(state().led5_yellow_blinking());
  contaminate(50);
  EXPECT_TRUE(state().led5_yellow_blinking());
  contaminate(0);
  EXPECT_FALSE(state().led5_yellow_blinking());
}

// Device.SetRestartButton: held, the button turns LED3 red and the OSSD off [RS4 manual §4.3]
// "Während der Betätigung der Restart-Taste sind die sicheren Ausgänge OSSD 1 und OSSD 2 des RS4
// abgeschaltet; die Anzeige am Scanner (LED 3) leuchtet rot"; at the release the press acts as the
// reset signal only if it lasted 0.12..5 s ("Die Dauer des Rücksetz-Signals muss zwischen 0,12
// und 5 Sekunden betragen"): after a protective-field violation a 119 ms hold leaves the restart
// interlock, a 120 ms hold releases it. PressRestart while the button is held: FAILED_PRECONDITION.
TEST_F(RpcRs4Test, RestartButtonHeldAndReleased) {
  boot();
  const auto button = [&](bool pressed) { return set_restart_button(pressed); };
  ASSERT_TRUE(button(true).ok());
  advance(40);
  auto s = state();
  EXPECT_TRUE(s.restart_button_held());
  EXPECT_TRUE(s.led3_red());
  EXPECT_FALSE(s.ossd());
  EXPECT_FALSE(s.input().ossd());
  {
    grpc::ClientContext ctx;
    v1::PressRestartRequest req;
    req.set_address(4);
    req.set_duration_ms(200);
    v1::Empty e;
    const auto status = device_stub_->PressRestart(&ctx, req, &e);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
    EXPECT_NE(status.error_message().find("already held"), std::string::npos)
        << status.error_message();
  }
  advance(6000);  // held long: still red, still off
  EXPECT_TRUE(state().led3_red());
  EXPECT_FALSE(state().ossd());
  ASSERT_TRUE(button(false).ok());
  EXPECT_FALSE(state().led3_red());
  EXPECT_FALSE(state().restart_button_held());
  EXPECT_TRUE(run_until(v1::CONDITION_OSSD_ON, 200)) << "no interlock pending: on again";

  v1::AddObstacleResponse obstacle;
  ASSERT_TRUE(violate_field(v1::FIELD_KIND_PROTECTIVE, obstacle).ok());
  ASSERT_TRUE(run_until(v1::CONDITION_OSSD_OFF, 1000));
  ASSERT_TRUE(remove_obstacle(obstacle.obstacle_id()).ok());
  advance(200);
  ASSERT_FALSE(state().ossd()) << "restart interlock";
  ASSERT_TRUE(button(true).ok());
  advance(119);
  ASSERT_TRUE(button(false).ok());
  EXPECT_FALSE(run_until(v1::CONDITION_OSSD_ON, 500)) << "119 ms is no reset signal";
  ASSERT_TRUE(button(true).ok());
  advance(120);
  EXPECT_FALSE(state().ossd()) << "not before the release";
  ASSERT_TRUE(button(false).ok());
  EXPECT_TRUE(run_until(v1::CONDITION_OSSD_ON, 500)) << "120 ms releases the interlock";
}

TEST_F(RpcRs4Test, BadInputGetsASpecificStatus) {
  v1::Empty e;
  {
    const auto s = set_contamination(9, 0);
    EXPECT_EQ(s.error_code(), grpc::StatusCode::NOT_FOUND);
    EXPECT_EQ(s.error_message(), "no RS4 at station 9 (stations: 4)");
  }
  {
    const auto s = set_contamination(200, 0);
    EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
    EXPECT_EQ(bad_field(s), "address");
  }
  {
    const auto s = set_contamination(4, 101);
    EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
    EXPECT_EQ(bad_field(s), "percent");
  }
  v1::AddObstacleResponse id;
  {
    grpc::ClientContext ctx;
    v1::AddObstacleRequest req;
    req.set_address(4);
    req.mutable_circle()->set_radius(-1);
    const auto s = device_stub_->AddObstacle(&ctx, req, &id);
    EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
    EXPECT_EQ(bad_field(s), "circle");
  }
  {
    grpc::ClientContext ctx;
    v1::AddObstacleRequest req;
    req.set_address(4);
    for (int i = 0; i < 10; ++i) req.mutable_contour()->add_mm(1000);
    const auto s = device_stub_->AddObstacle(&ctx, req, &id);
    EXPECT_EQ(bad_field(s), "contour.mm");
    EXPECT_NE(s.error_message().find("529 segments"), std::string::npos);
  }
  {
    grpc::ClientContext ctx;
    v1::AddObstacleRequest req;
    req.set_address(4);
    EXPECT_EQ(bad_field(device_stub_->AddObstacle(&ctx, req, &id)), "shape");
  }
  {
    grpc::ClientContext ctx;
    v1::RunUntilRequest req;
    req.set_address(4);
    req.set_timeout_ms(10);
    v1::RunUntilResponse r;
    EXPECT_EQ(bad_field(time_stub_->RunUntil(&ctx, req, &r)), "condition");
  }
  {
    grpc::ClientContext ctx;
    v1::FaultRequest req;
    req.set_address(4);
    EXPECT_EQ(bad_field(device_stub_->InjectFault(&ctx, req, &e)), "fault");
  }
  {
    // Before the boot no field pair is active: the shortcut has nothing to violate.
    const auto s = violate_field(v1::FIELD_KIND_PROTECTIVE, id);
    EXPECT_EQ(s.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
    google::rpc::Status rich;
    ASSERT_TRUE(rich.ParseFromString(s.error_details()));
    google::rpc::PreconditionFailure failure;
    ASSERT_TRUE(rich.details(0).UnpackTo(&failure));
    EXPECT_EQ(failure.violations(0).type(), "STATE");
  }
}

TEST_F(RpcRs4Test, InjectedFaultSwitchesTheOssdOff) {
  boot();
  grpc::ClientContext ctx;
  v1::FaultRequest req;
  req.set_address(4);
  req.set_fault(v1::FAULT_MOTOR_SPEED);
  v1::Empty e;
  ASSERT_TRUE(device_stub_->InjectFault(&ctx, req, &e).ok());
  ASSERT_TRUE(run_until(v1::CONDITION_OSSD_OFF, 1000));
  const auto s = state();
  EXPECT_TRUE(s.input().error());
  ASSERT_EQ(s.faults_present_size(), 1);
}

TEST_F(RpcRs4Test, SafetyFaultPassivatesTheHostAndSilenceDropsTheConnection) {
  boot();
  const auto passivations = [this] {
    std::uint64_t n = 0;
    executor_.run([&] { n = segment_.fhost().counters().passivations; });
    return n;
  };
  const auto before = passivations();
  v1::Empty e;
  ASSERT_TRUE(inject_safety_fault(v1::SAFETY_FAULT_CORRUPT_CRC2, 1).ok());
  advance(200);
  EXPECT_EQ(passivations(), before + 1);  // a CRC2 error passivates [IEC 61784-3-3 CRC]
  {
    grpc::ClientContext ctx;
    v1::SetSilencedRequest req;
    req.set_address(4);
    req.set_silenced(true);
    ASSERT_TRUE(faults_stub_->SetSilenced(&ctx, req, &e).ok());
  }
  advance(2000);  // beyond the 200 ms DP watchdog of the segment's master
  EXPECT_FALSE(state().connected());
  {
    const auto req = bus_fault_request(4, v1::BUS_FAULT_KIND_DELAY, v1::DIRECTION_TO_STATION, 1);
    v1::BusFaultResponse r;
    const auto s = unary(*faults_stub_, &v1::Faults::Stub::InjectBusFault, req, r);
    EXPECT_EQ(bad_field(s), "delay_ms");
  }
}

// The PLC's view (DeviceState.plc): a CRC2 error counts and passivates; a muted F-device lets
// F_WD_Time expire and the PLC reads fail-safe 0 (OSSD bit 0) while the scanner's OSSDs stay
// on; with good PDUs again the F-host raises ACK_REQ and keeps the fail-safe values until the
// operator acknowledges (this segment has no automatic ACK_REI) [RS4 manual §7.3.2].
TEST_F(RpcRs4Test, ThePlcSeesFailSafeValuesWhileTheFHostIsPassivated) {
  boot();
  advance(50);  // the F-host unwraps the RS4's PDU one cycle later
  auto plc = state().plc();
  ASSERT_TRUE(plc.present());
  EXPECT_EQ(plc.fhost_state(), "run");
  EXPECT_TRUE(plc.input().ossd());
  EXPECT_TRUE(plc.data_exchange());
  const auto passivations = plc.passivations();
  const auto safety_fault = [this](v1::SafetyFault fault, std::uint32_t count) {
    ASSERT_TRUE(inject_safety_fault(fault, count).ok());
  };
  safety_fault(v1::SAFETY_FAULT_CORRUPT_CRC2, 1);
  advance(200);
  plc = state().plc();
  EXPECT_EQ(plc.crc_errors(), 1U);
  EXPECT_EQ(plc.passivations(), passivations + 1);

  safety_fault(v1::SAFETY_FAULT_MUTE, 1);
  advance(1000);
  const auto muted = state();
  EXPECT_TRUE(muted.ossd());                 // the scanner still has its OSSDs on …
  EXPECT_FALSE(muted.plc().input().ossd());  // … the PLC reads the fail-safe 0
  EXPECT_EQ(muted.plc().input_byte(), 0U);
  EXPECT_NE(muted.plc().fhost_state(), "run");
  EXPECT_GT(muted.plc().watchdog_timeouts(), 0U);
  {
    grpc::ClientContext ctx;
    v1::StationRequest req;
    req.set_address(4);
    v1::Empty e;
    ASSERT_TRUE(faults_stub_->ClearSafetyFaults(&ctx, req, &e).ok());
  }
  advance(1000);
  plc = state().plc();
  EXPECT_EQ(plc.fhost_state(), "ack-required");
  EXPECT_FALSE(plc.input().ossd());
  executor_.run([this] { segment_.ack_rei(); });  // the operator's acknowledgement
  advance(200);
  plc = state().plc();
  EXPECT_EQ(plc.fhost_state(), "run");
  EXPECT_TRUE(plc.input().ossd());
  EXPECT_GT(plc.reintegrations(), 0U);
}

// A long Advance runs in slices of loop time: the other calls are served meanwhile (each Now
// sees a later simulated time than the one before), and when its client cancels, simulated
// time stops at the next slice instead of running on to the end (24 h here: minutes of CPU).
TEST_F(RpcRs4Test, ALongAdvanceLeavesTheLoopToOtherCallsAndStopsWhenCancelled) {
  const auto now_ns = [this] {
    grpc::ClientContext ctx;
    ctx.set_deadline(std::chrono::system_clock::now() + 5s);
    v1::Empty e;
    v1::TimeResponse t;
    const auto s = time_stub_->Now(&ctx, e, &t);
    EXPECT_TRUE(s.ok()) << s.error_message();
    return t.now_ns();
  };
  const std::int64_t t0 = now_ns();
  grpc::ClientContext long_ctx;
  auto advance = std::async(std::launch::async, [&] {
    v1::AdvanceRequest req;
    req.set_duration_ms(86'400'000);
    v1::TimeResponse t;
    return time_stub_->Advance(&long_ctx, req, &t);
  });
  // While it runs: Now answers, and simulated time has moved on between two answers.
  std::int64_t seen = t0;
  int moved = 0;
  for (int i = 0; i < 500 && moved < 3; ++i) {
    const std::int64_t t = now_ns();
    if (t > seen) ++moved;
    seen = t;
  }
  EXPECT_GE(moved, 3) << "Now was not served while Advance ran";
  EXPECT_LT(seen - t0, std::int64_t{86'400'000} * 1'000'000) << "Advance ended: too short";
  long_ctx.TryCancel();
  ASSERT_EQ(advance.wait_for(10s), std::future_status::ready);
  EXPECT_EQ(advance.get().error_code(), grpc::StatusCode::CANCELLED);
  // The server's handler stops within a slice: simulated time stands still afterwards.
  bool still = false;
  for (int i = 0; i < 100 && !still; ++i) {
    const std::int64_t a = now_ns();
    std::this_thread::sleep_for(30ms);  // longer than a slice (20 ms)
    still = now_ns() == a;
  }
  EXPECT_TRUE(still) << "simulated time kept running after the client cancelled";
}

// rs4sim.v1.Run: one call names what the run serves (the live page asks it instead of
// probing). Known answer: the four services the fixture registered, the server's own Run, and
// none of the services of other runs.
TEST_F(RpcRs4Test, RunDescribesTheServicesItServes) {
  auto stub = v1::Run::NewStub(channel_);
  grpc::ClientContext ctx;
  v1::RunDescription run;
  ASSERT_TRUE(stub->Describe(&ctx, v1::DescribeRunRequest{}, &run).ok());
  const std::vector<std::string> names(run.services().begin(), run.services().end());
  for (const char* served : {"rs4sim.v1.Device", "rs4sim.v1.Faults", "rs4sim.v1.Observation",
                             "rs4sim.v1.Run", "rs4sim.v1.SimTime"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), served), names.end()) << served;
  }
  for (const char* absent : {"rs4sim.v1.GsdStations", "rs4sim.v1.BusMaster", "rs4sim.v1.Archive",
                             "rs4sim.v1.GridScan", "rs4sim.v1.Proxy"}) {
    EXPECT_EQ(std::find(names.begin(), names.end(), absent), names.end()) << absent;
  }
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
}

// SimTime's start_ns is where the run's clock stood when its services were set up: the time
// since the run began is now_ns - start_ns, whatever the clock's origin (a simulated run's
// clock starts at 1 h, not 0).
TEST_F(RpcRs4Test, TheTimeSinceTheRunBeganIsNowMinusStart) {
  grpc::ClientContext at_start;
  v1::TimeResponse start;
  ASSERT_TRUE(time_stub_->Now(&at_start, v1::Empty{}, &start).ok());
  EXPECT_EQ(start.now_ns(), start.start_ns());  // nothing has run yet
  boot();
  grpc::ClientContext ctx;
  v1::TimeResponse before;
  ASSERT_TRUE(time_stub_->Now(&ctx, v1::Empty{}, &before).ok());
  EXPECT_GT(before.start_ns(), 0);
  // the boot: ≈30 s [RS4 manual §7.1.1], less than a minute
  EXPECT_GE(before.now_ns() - before.start_ns(), 30'000'000'000);
  EXPECT_LT(before.now_ns() - before.start_ns(), 60'000'000'000);
  advance(1500);
  grpc::ClientContext again;
  v1::TimeResponse after;
  ASSERT_TRUE(time_stub_->Now(&again, v1::Empty{}, &after).ok());
  EXPECT_EQ(after.start_ns(), before.start_ns());
  EXPECT_EQ(after.now_ns() - before.now_ns(), 1'500'000'000);
}

TEST_F(RpcRs4Test, StandardHealthServiceAnswersServing) {
  grpc::GenericStub stub(channel_);
  grpc::ClientContext ctx;
  const grpc::Slice empty;
  grpc::ByteBuffer request(&empty, 1);  // HealthCheckRequest{service = ""}: no bytes
  grpc::ByteBuffer response;
  std::promise<grpc::Status> done;
  stub.UnaryCall(&ctx, "/grpc.health.v1.Health/Check", grpc::StubOptions(), &request, &response,
                 [&done](const grpc::Status& s) { done.set_value(s); });
  ASSERT_TRUE(done.get_future().get().ok());
  std::vector<grpc::Slice> slices;
  ASSERT_TRUE(response.Dump(&slices).ok());
  std::string bytes;
  for (const auto& s : slices) bytes.append(reinterpret_cast<const char*>(s.begin()), s.size());
  EXPECT_EQ(bytes, std::string("\x08\x01", 2));  // status = SERVING
}

}  // namespace
}  // namespace rs4sim::rpc
