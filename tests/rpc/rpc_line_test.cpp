// rs4sim.v1.GridScan, Metron and Polaris (devices.proto) end to end: a real gRPC server on
// loopback in front of each device's core, whose loop runs on its own thread as in
// `rs4sim run --device X --grpc`. The link is this test: it hands the core bytes and time on
// the loop (the manual clock) and takes what it sends, through the same tap as the run.
#include "google/rpc/error_details.pb.h"
#include "google/rpc/status.pb.h"
#include "http_front.h"
#include "rpc/device_target.h"
#include "rpc/executor.h"
#include "rpc/gridscan_service.h"
#include "rpc/metron_service.h"
#include "rpc/polaris_service.h"
#include "rpc/rs4_services.h"
#include "rpc/server.h"
#include "rpc_calls.h"
#include "rs4sim/v1/devices.grpc.pb.h"
#include "test_loop.h"

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>
#include <gtest/gtest.h>

#include <grpcpp/create_channel.h>
#include <grpcpp/security/credentials.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <thread>
#include <vector>

// A use of a field marked [deprecated = true], on purpose (its old clients still work).
#define RS4SIM_DEPRECATED_FIELD(statement)                                                       \
  _Pragma("GCC diagnostic push") _Pragma("GCC diagnostic ignored \"-Wdeprecated-declarations\"") \
      statement;                                                                                 \
  _Pragma("GCC diagnostic pop")

namespace rs4sim::rpc {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;

std::vector<std::uint32_t> list(const google::protobuf::RepeatedField<std::uint32_t>& r) {
  return {r.begin(), r.end()};
}

// The loop, the manual clock, the event target and the server of one device.
class LineFixture : public ::testing::Test, protected TestLoop {
 protected:
  // The event target first (the services take its hub), as the run builds them.
  void watch(stream::DeviceKind kind, std::unique_ptr<Watcher> watcher) {
    target_ = std::make_unique<LineDeviceTarget>(kind, std::move(watcher), clock_, io_);
  }
  // Starts the loop and serves `service` beside the device's Observation service.
  void serve(grpc::Service& service) {
    observation_ = std::make_unique<ObservationService>(RunContext{*target_, executor_});
    start_loop();
    server_ = std::make_unique<RpcServer>(
        ServerOptions{}, std::vector<grpc::Service*>{&service, observation_.get()});
    channel_ = grpc::CreateChannel(server_->address(), grpc::InsecureChannelCredentials());
    observation_stub_ = v1::Observation::NewStub(channel_);
  }
  void TearDown() override {
    if (server_) server_->shutdown();
    if (target_) executor_.run([this] { target_->stop(); });
    stop_loop();
  }
  // As a link: bytes at now, then the clock from deadline to deadline for `span`; returns
  // what the device sent meanwhile.
  std::vector<Bytes> exchange(stream::ByteDevice& d, const Bytes& request,
                              stream::Duration span = 50ms) {
    std::vector<Bytes> sent;
    executor_.run([&] {
      if (!request.empty()) d.on_bytes(request, clock_.now());
      const auto until = clock_.now() + span;
      for (;;) {
        while (auto f = d.take_transmit()) sent.push_back(*f);
        const auto next = d.next_deadline();
        if (!next || *next > until) break;
        clock_.set(std::max(*next, clock_.now()));
        d.on_time(clock_.now());
      }
      clock_.set(until);
      d.on_time(until);
      while (auto f = d.take_transmit()) sent.push_back(*f);
    });
    return sent;
  }
  LineContext context(TappedByteDevice& tap, std::uint8_t address) {
    return {executor_, clock_, address, tap, target_->events()};
  }
  // The device's events, its service at `address` and a stub of it, served.
  template <class Service, class Grpc, class Device>
  void start(stream::DeviceKind kind, std::unique_ptr<Watcher> watcher, std::uint8_t address,
             Device& device, TappedByteDevice& tap, std::unique_ptr<Service>& service,
             std::unique_ptr<typename Grpc::Stub>& stub) {
    watch(kind, std::move(watcher));
    service = std::make_unique<Service>(context(tap, address), device);
    serve(*service);
    stub = Grpc::NewStub(channel_);
  }
  // GetState of the device at `address` (the call is expected to succeed).
  template <class State, class Stub>
  static State state_of(Stub& stub, std::uint32_t address) {
    v1::LineDeviceRequest req;
    req.set_address(address);
    State out;
    const auto s = unary(stub, &Stub::GetState, req, out);
    EXPECT_TRUE(s.ok()) << s.error_message();
    return out;
  }
  // SetBlocked: these beams (elements) of the device at `address` interrupted.
  template <class Stub>
  static grpc::Status set_blocked(Stub& stub, const std::vector<std::uint32_t>& beams,
                                  std::uint32_t address) {
    v1::SetBlockedRequest req;
    req.set_address(address);
    for (const auto b : beams) req.add_blocked(b);
    return unary(stub, &Stub::SetBlocked, req);
  }
  // A fault request: fault `f` of the device at `address`, `late_ms` for LATE.
  template <class Request, class Fault>
  static Request fault_request(std::uint32_t address, Fault f, std::uint32_t late_ms) {
    Request req;
    req.set_address(address);
    req.set_fault(f);
    req.set_late_ms(late_ms);
    return req;
  }
  // InjectFault (`inject`) or ClearFault with `req`.
  template <class Stub, class Request>
  static grpc::Status inject_or_clear(Stub& stub, const Request& req, bool inject) {
    return inject ? unary(stub, &Stub::InjectFault, req) : unary(stub, &Stub::ClearFault, req);
  }

  stream::ManualClock clock_;
  std::unique_ptr<LineDeviceTarget> target_;
  std::unique_ptr<ObservationService> observation_;
  std::unique_ptr<RpcServer> server_;
  std::shared_ptr<grpc::Channel> channel_;
  std::unique_ptr<v1::Observation::Stub> observation_stub_;
};

// ==== Polaris ==============================================================================

// The Modbus CRC-16 of a frame [Modbus serial line V1.02 §6.2.2], appended low byte first;
// the expected frames below were computed by hand from this rule, not by our encoder.
class RpcPolarisTest : public LineFixture {
 protected:
  void SetUp() override {
    device_.on_time(clock_.now());  // (the loop does not run yet)
    start<PolarisService, v1::Polaris>(stream::DeviceKind::kPolaris, polaris_watcher(1, device_), 1,
                                       device_, tap_, service_, stub_);
  }
  v1::PolarisState state() { return state_of<v1::PolarisState>(*stub_, 1); }
  grpc::Status block(const std::vector<std::uint32_t>& beams, std::uint32_t address = 1) {
    return set_blocked(*stub_, beams, address);
  }
  grpc::Status fault(v1::PolarisFault f, bool inject, std::uint32_t late_ms = 0) {
    return inject_or_clear(*stub_, fault_request<v1::PolarisFaultRequest>(1, f, late_ms), inject);
  }

  // PL10, 16 beams, 485MB, slave 1, data block at 0x2000 (the defaults).
  polaris::Device device_{polaris::Options{}};
  TappedByteDevice tap_{device_};
  std::unique_ptr<PolarisService> service_;
  std::unique_ptr<v1::Polaris::Stub> stub_;
  // FC 04, register 0x2000, 1 word, CRC 0A3A.
  const Bytes read_ = {0x01, 0x04, 0x20, 0x00, 0x00, 0x01, 0x3A, 0x0A};
};

TEST_F(RpcPolarisTest, BlockedBeamsReachTheModbusAnswer) {
  auto s = state();
  EXPECT_EQ(s.address(), 1U);
  EXPECT_EQ(s.beams(), 16U);
  EXPECT_EQ(s.data_mode(), "485MB");
  EXPECT_FALSE(s.pn1());
  EXPECT_EQ(list(s.data_block()), (std::vector<std::uint32_t>{0xFFFF}));
  EXPECT_TRUE(s.last_frame().frame().empty());

  ASSERT_TRUE(block({9, 10, 11, 12, 13}).ok());
  s = state();
  EXPECT_EQ(list(s.blocked()), (std::vector<std::uint32_t>{9, 10, 11, 12, 13}));
  EXPECT_TRUE(s.pn1());
  EXPECT_FALSE(s.pn2());
  ASSERT_EQ(s.objects_size(), 1);
  EXPECT_EQ(s.objects(0).first(), 9U);
  EXPECT_EQ(s.objects(0).last(), 13U);
  EXPECT_EQ(s.start_address(), 0x2000U);
  // 1 = beam free, beam 1 in bit 0: beams 9..13 clear bits 8..12.
  EXPECT_EQ(list(s.data_block()), (std::vector<std::uint32_t>{0xE0FF}));

  const auto sent = exchange(tap_, read_);
  const Bytes answer = {0x01, 0x04, 0x02, 0xE0, 0xFF, 0xB0, 0xB0};
  ASSERT_EQ(sent.size(), 1U);
  EXPECT_EQ(sent[0], answer);
  s = state();
  EXPECT_EQ(s.counters().requests(), 1U);
  EXPECT_EQ(s.counters().frames_sent(), 1U);
  EXPECT_EQ(s.last_frame().frame(), std::string(answer.begin(), answer.end()));
  EXPECT_GT(s.last_frame().sent_ns(), 0);

  ASSERT_TRUE(block({}).ok());  // all free again
  EXPECT_EQ(list(state().data_block()), (std::vector<std::uint32_t>{0xFFFF}));
}

// Auto-calibration from the API (the autocal input): 0.4 s × 16 beams = 6.4 s during which a
// data read gets exception 06 Server Device Busy, then the data again [Polaris manual §7.2]
// (docs/polaris.md "Auto-calibration"); the frames' CRCs were worked out by hand.
TEST_F(RpcPolarisTest, CalibrateMakesTheDataBusyForPointFourSecondsABeam) {
  const auto calibrate = [this] {
    v1::LineDeviceRequest req;
    req.set_address(1);
    return unary(*stub_, &v1::Polaris::Stub::Calibrate, req);
  };
  auto s = state();
  EXPECT_FALSE(s.calibrating());
  EXPECT_EQ(s.calibration_end_ns(), 0);
  EXPECT_EQ(s.direction(), "direct");
  EXPECT_EQ(s.detection(), "object");
  EXPECT_EQ(s.bit_order(), "lsb");
  EXPECT_EQ(s.pn2_filter(), 1U);
  EXPECT_EQ(s.scan_time_ms(), 100U);
  EXPECT_TRUE(s.nak_on_error());

  const auto started = state().now_ns();
  ASSERT_TRUE(calibrate().ok());
  s = state();
  EXPECT_TRUE(s.calibrating());
  EXPECT_EQ(s.calibration_end_ns(), started + 6'400'000'000);
  const auto again = calibrate();
  EXPECT_EQ(again.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
  EXPECT_NE(again.error_message().find("auto-calibration runs"), std::string::npos)
      << again.error_message();
  // address 1, FC 04 | 0x80, exception 06, CRC C3 02
  EXPECT_EQ(exchange(tap_, read_), (std::vector<Bytes>{{0x01, 0x84, 0x06, 0xC3, 0x02}}));
  EXPECT_EQ(state().counters().busy(), 1U);
  (void)exchange(tap_, {}, 6400ms);  // past the end
  s = state();
  EXPECT_FALSE(s.calibrating());
  EXPECT_EQ(s.calibrations(), 1U);
  // 1 word, all 16 beams free, CRC B8 80
  EXPECT_EQ(exchange(tap_, read_), (std::vector<Bytes>{{0x01, 0x04, 0x02, 0xFF, 0xFF, 0xB8, 0x80}}));
  s.Clear();
  grpc::ClientContext ctx;
  v1::LineDeviceRequest wrong;
  wrong.set_address(0);
  v1::Empty e;
  EXPECT_EQ(stub_->Calibrate(&ctx, wrong, &e).error_code(), grpc::StatusCode::INVALID_ARGUMENT);
}

TEST_F(RpcPolarisTest, FaultsActOnTheWireUntilCleared) {
  ASSERT_TRUE(fault(v1::POLARIS_FAULT_BAD_CRC, true).ok());
  EXPECT_EQ(list(state().data_block()), (std::vector<std::uint32_t>{0xFFFF}));
  auto sent = exchange(tap_, read_);
  ASSERT_EQ(sent.size(), 1U);
  // 01 04 02 FF FF, CRC 80B8 with its high byte inverted.
  EXPECT_EQ(sent[0], (Bytes{0x01, 0x04, 0x02, 0xFF, 0xFF, 0xB8, 0x7F}));
  const auto faulty = state();
  EXPECT_EQ(
      std::vector<std::string>(faulty.faults_present().begin(), faulty.faults_present().end()),
      (std::vector<std::string>{"bad-crc"}));
  ASSERT_TRUE(fault(v1::POLARIS_FAULT_BAD_CRC, false).ok());

  ASSERT_TRUE(fault(v1::POLARIS_FAULT_SILENT, true).ok());
  EXPECT_TRUE(exchange(tap_, read_).empty());
  EXPECT_EQ(state().counters().suppressed(), 1U);
  RS4SIM_DEPRECATED_FIELD(ASSERT_TRUE(fault(v1::POLARIS_FAULT_NO_ANSWER, false).ok()));  // old name

  ASSERT_TRUE(fault(v1::POLARIS_FAULT_LATE, true, 30).ok());
  EXPECT_EQ(state().late_ms(), 30U);
  EXPECT_TRUE(exchange(tap_, read_, 20ms).empty());  // not within 20 ms ...
  EXPECT_EQ(exchange(tap_, {}, 40ms).size(), 1U);    // ... but later
  ASSERT_TRUE(fault(v1::POLARIS_FAULT_LATE, false).ok());
  EXPECT_TRUE(state().faults_present().empty());
  EXPECT_EQ(exchange(tap_, read_).size(), 1U);
}

TEST_F(RpcPolarisTest, BadInputGetsASpecificStatus) {
  auto s = block({3, 17});
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(s), "blocked[1]");
  s = block({0});
  EXPECT_EQ(bad_field(s), "blocked[0]");
  s = block({3}, 0);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(s), "address");
  s = block({3}, 248);
  EXPECT_EQ(bad_field(s), "address");
  s = block({3}, 2);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_NE(s.error_message().find("answers to 1"), std::string::npos) << s.error_message();
  s = fault(v1::POLARIS_FAULT_UNSPECIFIED, true);
  EXPECT_EQ(bad_field(s), "fault");
  s = fault(static_cast<v1::PolarisFault>(42), false);
  EXPECT_EQ(bad_field(s), "fault");
  s = fault(v1::POLARIS_FAULT_LATE, true, 0);
  EXPECT_EQ(bad_field(s), "late_ms");
  s = fault(v1::POLARIS_FAULT_LATE, true, 10'001);
  EXPECT_EQ(bad_field(s), "late_ms");
  EXPECT_TRUE(state().blocked().empty());  // nothing changed
  EXPECT_TRUE(state().faults_present().empty());
  {
    grpc::ClientContext ctx;
    v1::LineDeviceRequest req;
    req.set_address(7);
    v1::PolarisState out;
    EXPECT_EQ(stub_->GetState(&ctx, req, &out).error_code(), grpc::StatusCode::NOT_FOUND);
  }
  // The RS4's Observation.GetState on a Polaris run names the mistake.
  v1::DeviceState out;
  const auto rs4 =
      unary(*observation_stub_, &v1::Observation::Stub::GetState, station_request(1), out);
  EXPECT_EQ(rs4.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
  EXPECT_NE(rs4.error_message().find("polaris"), std::string::npos) << rs4.error_message();
}

// The shared event stream: the snapshot, then the changes SetBlocked makes.
TEST_F(RpcPolarisTest, StateChangesReachTheSharedEventStream) {
  grpc::ClientContext ctx;
  v1::StreamEventsRequest req;
  req.add_addresses(1);
  auto reader = observation_stub_->StreamEvents(&ctx, req);
  std::vector<std::string> seen;
  v1::Event e;
  // The snapshot first (the stream has subscribed once it arrived).
  for (int i = 0; i < 4 && reader->Read(&e); ++i) {
    ASSERT_TRUE(e.has_state());
    EXPECT_EQ(e.address(), 1U);
    seen.push_back(e.state().what() + ":" + e.state().previous() + ">" + e.state().to());
  }
  EXPECT_EQ(seen,
            (std::vector<std::string>{"pn1:>off", "pn2:>off", "beams:>none", "calibrating:>off"}));
  ASSERT_TRUE(block({2, 3, 7}).ok());
  seen.clear();
  for (int i = 0; i < 3 && reader->Read(&e); ++i) {
    seen.push_back(e.state().what() + ":" + e.state().previous() + ">" + e.state().to());
  }
  // Beams 2-3 and 7: two objects, so PN2 too [Polaris manual §3].
  EXPECT_EQ(seen, (std::vector<std::string>{"pn1:off>on", "pn2:off>on", "beams:none>2-3,7"}));
  ctx.TryCancel();
  (void)reader->Finish();

  grpc::ClientContext bad_ctx;
  v1::StreamEventsRequest bad;
  bad.add_addresses(4);
  auto refused = observation_stub_->StreamEvents(&bad_ctx, bad);
  EXPECT_FALSE(refused->Read(&e));
  EXPECT_EQ(refused->Finish().error_code(), grpc::StatusCode::NOT_FOUND);
}

// ==== GridScan =============================================================================

class RpcGridScanTest : public LineFixture {
 protected:
  void SetUp() override {
    start<GridScanService, v1::GridScan>(stream::DeviceKind::kGridScan,
                                         gridscan_watcher(0, device_), 0, device_, tap_, service_,
                                         stub_);
  }
  void power_up() {
    executor_.run([this] { device_.power_on(clock_.now()); });
    (void)exchange(tap_, {}, 2s);  // ready after at most 1.7 s [GridScan manual §11]
  }
  v1::GridScanState state() { return state_of<v1::GridScanState>(*stub_, 0); }
  grpc::Status door(std::uint32_t position) {
    v1::SetDoorRequest req;
    req.set_position(position);
    return unary(*stub_, &v1::GridScan::Stub::SetDoor, req);
  }
  grpc::Status block(const std::vector<std::uint32_t>& elements) {
    return set_blocked(*stub_, elements, 0);
  }
  grpc::Status soiling(std::uint32_t level) {
    v1::SetSoilingRequest req;
    req.set_level(level);
    return unary(*stub_, &v1::GridScan::Stub::SetSoiling, req);
  }
  grpc::Status fault(v1::GridScanFault f, bool inject, std::uint32_t late_ms = 0,
                     std::uint32_t address = 0) {
    return inject_or_clear(*stub_, fault_request<v1::GridScanFaultRequest>(address, f, late_ms),
                           inject);
  }

  // 22 elements, blanking mode, door open.
  gridscan::Device device_{gridscan::Options{}};
  TappedByteDevice tap_{device_};
  std::unique_ptr<GridScanService> service_;
  std::unique_ptr<v1::GridScan::Stub> stub_;
};

TEST_F(RpcGridScanTest, SceneReachesTheStateBytes) {
  EXPECT_EQ(state().power(), "off");
  power_up();
  auto s = state();
  EXPECT_EQ(s.power(), "ready");
  EXPECT_EQ(s.mode(), "polling");
  EXPECT_EQ(s.configuration(), "blanking");
  EXPECT_EQ(s.elements(), 22U);
  EXPECT_EQ(s.led_tx_green(), "on");
  EXPECT_EQ(s.door_position(), 22U);
  EXPECT_FALSE(s.report_interrupted());
  // The power-up messages went out (Get version, then Reduced state [GridScan manual §9]).
  EXPECT_FALSE(s.last_frame().frame().empty());

  ASSERT_TRUE(door(10).ok());
  ASSERT_TRUE(block({3, 15}).ok());
  ASSERT_TRUE(soiling(2).ok());
  s = state();
  EXPECT_EQ(s.door_position(), 10U);
  EXPECT_EQ(s.report_door_position(), 10U);
  EXPECT_EQ(list(s.blocked()), (std::vector<std::uint32_t>{3, 15}));
  // Element 3 is below the door edge (bit 8); 15 is covered by the door anyway.
  EXPECT_TRUE(s.report_interrupted());
  EXPECT_EQ(s.soiling(), 2U);
  EXPECT_EQ(s.report_maintenance(), 2U);
  ASSERT_FALSE(s.report_interrupted_elements().empty());
  EXPECT_EQ(s.report_interrupted_elements(0), 3U);
  ASSERT_TRUE(block({15}).ok());
  EXPECT_FALSE(state().report_interrupted());  // above the door edge: blanked
}

TEST_F(RpcGridScanTest, EveryFaultIsInjectedAndCleared) {
  power_up();
  ASSERT_TRUE(fault(v1::GRID_SCAN_FAULT_LATE, true, 25).ok());
  ASSERT_TRUE(fault(v1::GRID_SCAN_FAULT_WRONG_SEQ, true).ok());
  ASSERT_TRUE(fault(v1::GRID_SCAN_FAULT_DIRECTION_BIT, true).ok());
  ASSERT_TRUE(fault(v1::GRID_SCAN_FAULT_BAD_CRC, true).ok());
  ASSERT_TRUE(fault(v1::GRID_SCAN_FAULT_INTERNAL_FAILURE, true).ok());
  ASSERT_TRUE(fault(v1::GRID_SCAN_FAULT_SILENT, true).ok());
  ASSERT_TRUE(fault(v1::GRID_SCAN_FAULT_CONFIG_NOT_SET, true).ok());
  auto s = state();
  EXPECT_EQ(std::vector<std::string>(s.faults_present().begin(), s.faults_present().end()),
            (std::vector<std::string>{"late", "wrong-seq", "direction-bit", "bad-crc",
                                      "internal-failure", "silent", "config-not-set"}));
  EXPECT_EQ(s.late_ms(), 25U);
  EXPECT_TRUE(s.report_internal_failure());       // bit 9 [GridScan manual §10.2.3]
  EXPECT_EQ(state().led_rx_red(), "blink-fast");  // [GridScan manual §13]
  for (const auto f : {v1::GRID_SCAN_FAULT_LATE, v1::GRID_SCAN_FAULT_WRONG_SEQ,
                       v1::GRID_SCAN_FAULT_DIRECTION_BIT, v1::GRID_SCAN_FAULT_BAD_CRC,
                       v1::GRID_SCAN_FAULT_INTERNAL_FAILURE, v1::GRID_SCAN_FAULT_SILENT,
                       v1::GRID_SCAN_FAULT_CONFIG_NOT_SET}) {
    ASSERT_TRUE(fault(f, false).ok()) << f;
  }
  s = state();
  EXPECT_TRUE(s.faults_present().empty());
  EXPECT_EQ(s.late_ms(), 0U);
  EXPECT_FALSE(s.report_internal_failure());
}

// LATE_ANSWER, LATE's deprecated old name, still parses (by name, as JSON and the Python
// package send it) to the same value; what the server prints is LATE.
TEST_F(RpcGridScanTest, TheOldNameOfLateIsTheSameFault) {
  v1::GridScanFault old_name{};
  ASSERT_TRUE(v1::GridScanFault_Parse("GRID_SCAN_FAULT_LATE_ANSWER", &old_name));
  EXPECT_EQ(old_name, v1::GRID_SCAN_FAULT_LATE);
  EXPECT_EQ(v1::GridScanFault_Name(old_name), "GRID_SCAN_FAULT_LATE");
  power_up();
  ASSERT_TRUE(fault(old_name, true, 40).ok());
  EXPECT_EQ(state().late_ms(), 40U);
  EXPECT_EQ(state().faults_present(0), "late");
  ASSERT_TRUE(fault(v1::GRID_SCAN_FAULT_LATE, false).ok());
  EXPECT_TRUE(state().faults_present().empty());
}

// The power-up Reduced state (ID 0xB0, SeqCnt 1) of door 10 with element 3 interrupted:
// payload 0A 01 [GridScan manual §9.2.4], CRC-32/MPEG-2 over SeqCnt, ID and payload, least
// significant byte first [GridScan manual §9.2]; the CRCs were computed by that rule outside
// the project. Each fault changes the frame as the controller must notice
// [GridScan manual §10.2.2]; after ClearFault the frame is right again.
TEST_F(RpcGridScanTest, FaultsReachThePowerUpStateFrame) {
  ASSERT_TRUE(door(10).ok());
  ASSERT_TRUE(block({3}).ok());
  const auto frame = [](const Bytes& rest) {
    Bytes f = {0x43, 0x45, 0x44, 0x45};  // sync "CEDE"
    f.insert(f.end(), rest.begin(), rest.end());
    return std::string(f.begin(), f.end());
  };
  const auto cycle = [this] {
    executor_.run([this] { device_.power_off(); });
    power_up();
    return state().last_frame().frame();
  };
  EXPECT_EQ(cycle(), frame({0x01, 0xB0, 0x0A, 0x01, 0x36, 0x9C, 0xDB, 0xFF}));
  ASSERT_TRUE(fault(v1::GRID_SCAN_FAULT_BAD_CRC, true).ok());  // bit 0 of the CRC's first byte
  EXPECT_EQ(cycle(), frame({0x01, 0xB0, 0x0A, 0x01, 0x37, 0x9C, 0xDB, 0xFF}));
  ASSERT_TRUE(fault(v1::GRID_SCAN_FAULT_BAD_CRC, false).ok());
  ASSERT_TRUE(fault(v1::GRID_SCAN_FAULT_WRONG_SEQ, true).ok());  // SeqCnt 2, not 1
  EXPECT_EQ(cycle(), frame({0x02, 0xB0, 0x0A, 0x01, 0x58, 0x2E, 0xAC, 0x9F}));
  ASSERT_TRUE(fault(v1::GRID_SCAN_FAULT_WRONG_SEQ, false).ok());
  ASSERT_TRUE(fault(v1::GRID_SCAN_FAULT_DIRECTION_BIT, true).ok());  // ID 0x30
  EXPECT_EQ(cycle(), frame({0x01, 0x30, 0x0A, 0x01, 0xB6, 0xDF, 0x8D, 0x13}));
  ASSERT_TRUE(fault(v1::GRID_SCAN_FAULT_DIRECTION_BIT, false).ok());
  EXPECT_EQ(cycle(), frame({0x01, 0xB0, 0x0A, 0x01, 0x36, 0x9C, 0xDB, 0xFF}));
}

// The curtain's own failures a controller must catch ([GridScan manual §10.1.1],
// [GridScan manual §10.1.2], [GridScan manual §10.2.2]): in GetState while present, gone
// after ClearFault; stuck elements by number.
TEST_F(RpcGridScanTest, TheCurtainsOwnFailuresAreInjectedByNameAndElement) {
  power_up();
  const auto stuck = [this](bool inject, std::vector<std::uint32_t> elements) {
    v1::GridScanFaultRequest req;
    req.set_fault(v1::GRID_SCAN_FAULT_STUCK_FREE);
    for (const auto e : elements) req.add_elements(e);
    return inject_or_clear(*stub_, req, inject);
  };
  for (const auto f :
       {v1::GRID_SCAN_FAULT_REPEAT_FRAMES, v1::GRID_SCAN_FAULT_INSERT_FRAMES,
        v1::GRID_SCAN_FAULT_TEST_IGNORED, v1::GRID_SCAN_FAULT_MODE_ACTIVATION_FAILS}) {
    ASSERT_TRUE(fault(f, true).ok()) << f;
  }
  ASSERT_TRUE(block({3, 4}).ok());
  ASSERT_TRUE(stuck(true, {3, 7}).ok());
  auto s = state();
  EXPECT_EQ(std::vector<std::string>(s.faults_present().begin(), s.faults_present().end()),
            (std::vector<std::string>{"repeat-frames", "insert-frames", "test-ignored",
                                      "stuck-free", "mode-activation-fails"}));
  EXPECT_EQ(std::vector<std::uint32_t>(s.stuck_free().begin(), s.stuck_free().end()),
            (std::vector<std::uint32_t>{3, 7}));
  // element 3's object is not seen; element 4's is
  EXPECT_EQ(std::vector<std::uint32_t>(s.report_interrupted_elements().begin(),
                                       s.report_interrupted_elements().end()),
            (std::vector<std::uint32_t>{4}));
  ASSERT_TRUE(stuck(false, {7}).ok());
  EXPECT_EQ(state().stuck_free_size(), 1);
  ASSERT_TRUE(stuck(false, {}).ok());  // every one
  EXPECT_EQ(state().stuck_free_size(), 0);
  EXPECT_EQ(state().report_interrupted_elements_size(), 2);
  // bad input
  EXPECT_EQ(bad_field(stuck(true, {})), "elements");
  EXPECT_EQ(bad_field(stuck(true, {23})), "elements");  // 22 elements
  EXPECT_EQ(bad_field(stuck(true, {0})), "elements");
  {
    grpc::ClientContext ctx;
    v1::GridScanFaultRequest req;
    req.set_fault(v1::GRID_SCAN_FAULT_BAD_CRC);
    req.add_elements(1);
    v1::Empty e;
    EXPECT_EQ(bad_field(stub_->InjectFault(&ctx, req, &e)), "elements");
  }
  for (const auto f :
       {v1::GRID_SCAN_FAULT_REPEAT_FRAMES, v1::GRID_SCAN_FAULT_INSERT_FRAMES,
        v1::GRID_SCAN_FAULT_TEST_IGNORED, v1::GRID_SCAN_FAULT_MODE_ACTIVATION_FAILS}) {
    ASSERT_TRUE(fault(f, false).ok()) << f;
  }
  EXPECT_TRUE(state().faults_present().empty());
}

TEST_F(RpcGridScanTest, SilentFaultKeepsThePowerUpMessagesOffTheLine) {
  ASSERT_TRUE(fault(v1::GRID_SCAN_FAULT_SILENT, true).ok());
  power_up();
  EXPECT_TRUE(state().last_frame().frame().empty());
  EXPECT_EQ(state().last_frame().sent_ns(), 0);
}

TEST_F(RpcGridScanTest, BadInputGetsASpecificStatus) {
  auto s = door(23);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(s), "position");
  s = block({1, 23});
  EXPECT_EQ(bad_field(s), "blocked[1]");
  s = soiling(4);
  EXPECT_EQ(bad_field(s), "level");
  s = fault(v1::GRID_SCAN_FAULT_UNSPECIFIED, true);
  EXPECT_EQ(bad_field(s), "fault");
  s = fault(v1::GRID_SCAN_FAULT_LATE, true, 0);
  EXPECT_EQ(bad_field(s), "late_ms");
  s = fault(v1::GRID_SCAN_FAULT_BAD_CRC, true, 0, 1);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::NOT_FOUND);
  s = fault(v1::GRID_SCAN_FAULT_BAD_CRC, true, 0, 256);
  EXPECT_EQ(bad_field(s), "address");
  const auto st = state();
  EXPECT_TRUE(st.faults_present().empty());
  EXPECT_TRUE(st.blocked().empty());
  EXPECT_EQ(st.soiling(), 0U);
}

// ==== METRON ===============================================================================

class RpcMetronTest : public LineFixture {
 protected:
  void SetUp() override {
    start<MetronService, v1::Metron>(stream::DeviceKind::kMetron, metron_watcher(5, device_), 5,
                                     device_, tap_, service_, stub_);
  }
  static metron::Options options() {
    metron::Options o;  // 24 beams, slave line mode
    o.node_enabled = true;
    o.node = 5;
    return o;
  }
  v1::MetronState state() { return state_of<v1::MetronState>(*stub_, 5); }
  grpc::Status block(const std::vector<std::uint32_t>& beams, std::uint32_t address = 5) {
    return set_blocked(*stub_, beams, address);
  }
  grpc::Status synchronised(bool on) {
    v1::SetSynchronisedRequest req;
    req.set_address(5);
    req.set_synchronised(on);
    return unary(*stub_, &v1::Metron::Stub::SetSynchronised, req);
  }
  // `old_delay_ms`: the deprecated name of late_ms, as an older client sends it.
  grpc::Status fault(v1::MetronFault f, bool inject, std::uint32_t late_ms = 0,
                     std::uint32_t old_delay_ms = 0) {
    auto req = fault_request<v1::MetronFaultRequest>(5, f, late_ms);
    RS4SIM_DEPRECATED_FIELD(req.set_delay_ms(old_delay_ms));
    return inject_or_clear(*stub_, req, inject);
  }

  metron::Device device_{options()};
  TappedByteDevice tap_{device_};
  std::unique_ptr<MetronService> service_;
  std::unique_ptr<v1::Metron::Stub> stub_;
};

TEST_F(RpcMetronTest, BeamsAndSynchronisationDriveTheOssds) {
  auto s = state();
  EXPECT_EQ(s.address(), 5U);
  EXPECT_EQ(s.line_mode(), "slave");
  EXPECT_TRUE(s.node_enabled());
  EXPECT_EQ(s.beams(), 24U);
  EXPECT_TRUE(s.ossd());
  EXPECT_EQ(s.ossd_function(), "enabled");
  EXPECT_EQ(s.counters().errors_size(), 5);

  ASSERT_TRUE(block({9, 10, 11, 12, 13}).ok());
  s = state();
  EXPECT_EQ(list(s.blocked()), (std::vector<std::uint32_t>{9, 10, 11, 12, 13}));
  EXPECT_FALSE(s.ossd());
  EXPECT_EQ(s.first_interrupted(), 9U);
  EXPECT_EQ(s.last_interrupted(), 13U);
  EXPECT_EQ(s.interrupted_count(), 5U);
  ASSERT_TRUE(block({}).ok());
  EXPECT_TRUE(state().ossd());

  ASSERT_TRUE(synchronised(false).ok());
  s = state();
  EXPECT_FALSE(s.synchronised());
  EXPECT_FALSE(s.ossd());
  ASSERT_TRUE(synchronised(true).ok());
  EXPECT_TRUE(state().ossd());
}

TEST_F(RpcMetronTest, EveryFaultIsInjectedAndCleared) {
  ASSERT_TRUE(fault(v1::METRON_FAULT_SILENT, true).ok());
  ASSERT_TRUE(fault(v1::METRON_FAULT_LATE, true, 40).ok());
  ASSERT_TRUE(fault(v1::METRON_FAULT_BAD_CHECKSUM, true).ok());
  ASSERT_TRUE(fault(v1::METRON_FAULT_WRONG_NODE, true).ok());
  ASSERT_TRUE(fault(v1::METRON_FAULT_TRUNCATE, true).ok());
  auto s = state();
  EXPECT_EQ(std::vector<std::string>(s.faults_present().begin(), s.faults_present().end()),
            (std::vector<std::string>{"silent", "late", "bad-checksum", "wrong-node", "truncate"}));
  EXPECT_EQ(s.late_ms(), 40U);
  RS4SIM_DEPRECATED_FIELD(EXPECT_EQ(s.delay_ms(), 40U));
  for (const auto f :
       {v1::METRON_FAULT_SILENT, v1::METRON_FAULT_LATE, v1::METRON_FAULT_BAD_CHECKSUM,
        v1::METRON_FAULT_WRONG_NODE, v1::METRON_FAULT_TRUNCATE}) {
    ASSERT_TRUE(fault(f, false).ok()) << f;
  }
  s = state();
  EXPECT_TRUE(s.faults_present().empty());
  EXPECT_EQ(s.late_ms(), 0U);
}

// delay_ms, the old name of late_ms, keeps working; both given must agree.
TEST_F(RpcMetronTest, TheDeprecatedDelayMsStillWorks) {
  ASSERT_TRUE(fault(v1::METRON_FAULT_LATE, true, 0, 25).ok());
  EXPECT_EQ(state().late_ms(), 25U);
  ASSERT_TRUE(fault(v1::METRON_FAULT_LATE, true, 30, 30).ok());
  EXPECT_EQ(state().late_ms(), 30U);
  const auto s = fault(v1::METRON_FAULT_LATE, true, 30, 31);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(s), "delay_ms");
  EXPECT_EQ(bad_field(fault(v1::METRON_FAULT_LATE, true, 0, 10001)), "delay_ms");
}

TEST_F(RpcMetronTest, BadInputGetsASpecificStatus) {
  auto s = block({25});
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(s), "blocked[0]");
  s = block({1}, 255);
  EXPECT_EQ(bad_field(s), "address");
  EXPECT_EQ(s.error_message(),
            "address: 255 is the broadcast address "
            "[METRON manual \"With node\"]; "
            "the curtain's is its node (0..254), or 0 without node mode");
  s = block({1}, 0);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::NOT_FOUND);
  s = fault(v1::METRON_FAULT_UNSPECIFIED, true);
  EXPECT_EQ(bad_field(s), "fault");
  s = fault(v1::METRON_FAULT_LATE, true);
  EXPECT_EQ(bad_field(s), "late_ms");
  EXPECT_TRUE(state().blocked().empty());
  EXPECT_TRUE(state().faults_present().empty());
}

// Without node mode the curtain answers to 0, and a wrong node cannot be provoked.
TEST(RpcMetronNoNodeTest, WrongNodeNeedsNodeMode) {
  stream::ManualClock clock;
  boost::asio::io_context io;
  auto work = boost::asio::make_work_guard(io);
  std::thread loop([&io] { io.run(); });
  AsioExecutor executor(io);
  metron::Device device{metron::Options{}};
  TappedByteDevice tap(device);
  MetronService service(LineContext{executor, clock, 0, tap, nullptr}, device);
  RpcServer server(ServerOptions{}, {&service});
  auto stub = v1::Metron::NewStub(
      grpc::CreateChannel(server.address(), grpc::InsecureChannelCredentials()));
  grpc::ClientContext ctx;
  v1::MetronFaultRequest req;
  req.set_fault(v1::METRON_FAULT_WRONG_NODE);
  v1::Empty e;
  const auto s = stub->InjectFault(&ctx, req, &e);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
  EXPECT_NE(s.error_message().find("node mode"), std::string::npos) << s.error_message();
  server.shutdown();
  work.reset();
  loop.join();
}

// ==== the same services as JSON over HTTP (docs/http.md) ===================================

TEST_F(RpcPolarisTest, JsonOverHttpIsTheSameService) {
  HttpFront h(io_, *server_);
  const auto a = h.call("rs4sim.v1.Polaris/SetBlocked", R"({"address": 1, "blocked": [3, 4]})");
  ASSERT_EQ(a.status, 200u) << a.body;
  const auto got = h.call("rs4sim.v1.Polaris/GetState", R"({"address": 1})");
  ASSERT_EQ(got.status, 200u) << got.body;
  EXPECT_EQ(from_json<v1::PolarisState>(got.body).SerializeAsString(), state().SerializeAsString());
  EXPECT_EQ(list(from_json<v1::PolarisState>(got.body).blocked()),
            (std::vector<std::uint32_t>{3, 4}));
  error_of(h.call("rs4sim.v1.Polaris/GetState", R"({"address": 2})"), 404, 5);
}

TEST_F(RpcGridScanTest, JsonOverHttpIsTheSameService) {
  HttpFront h(io_, *server_);
  const auto got = h.call("rs4sim.v1.GridScan/GetState", R"({"address": 0})");
  ASSERT_EQ(got.status, 200u) << got.body;
  EXPECT_EQ(from_json<v1::GridScanState>(got.body).SerializeAsString(),
            state().SerializeAsString());
  error_of(h.call("rs4sim.v1.GridScan/SetSoiling", R"({"address": 0, "level": 4})"), 400, 3);
}

TEST_F(RpcMetronTest, JsonOverHttpIsTheSameService) {
  HttpFront h(io_, *server_);
  const auto got = h.call("rs4sim.v1.Metron/GetState", R"({"address": 5})");
  ASSERT_EQ(got.status, 200u) << got.body;
  EXPECT_EQ(from_json<v1::MetronState>(got.body).SerializeAsString(), state().SerializeAsString());
  auto other = error_of(h.call("rs4sim.v1.Metron/GetState", R"({"address": 0})"), 404, 5);
  EXPECT_EQ(other.message(), "no METRON at address 0 (this run's METRON answers to 5)");
}

// ==== timing from the user, SW1, LEDs, calibration with an obstacle (gRPC and JSON) ==========

// One scan of the Polaris: the model table's second column, "PL 10-160 ... 0,6 1,0 16"
// [Polaris manual §2.1] (the fixture's 16 beams), or any time; ranges refused by field.
TEST_F(RpcPolarisTest, SetTimingPicksTheResponseColumnOrAnyTime) {
  HttpFront h(io_, *server_);
  EXPECT_EQ(state().scan_ns(), 600'000);  // first column: 0,6 ms
  EXPECT_EQ(state().response_column(), 1U);
  ASSERT_EQ(h.call("rs4sim.v1.Polaris/SetTiming", R"({"address": 1, "response_column": 2})").status,
            200u);
  EXPECT_EQ(state().scan_ns(), 1'000'000);  // second column: 1,0 ms
  EXPECT_EQ(state().response_column(), 2U);
  ASSERT_EQ(h.call("rs4sim.v1.Polaris/SetTiming", R"({"address": 1, "response_time_us": 750})")
                .status,
            200u);
  EXPECT_EQ(state().scan_ns(), 750'000);
  auto bad = error_of(
      h.call("rs4sim.v1.Polaris/SetTiming", R"({"address": 1, "response_time_us": 1000001})"),
      400, 3);
  EXPECT_NE(bad.message().find("outside 0..1000000"), std::string::npos) << bad.message();
  grpc::ClientContext ctx;
  v1::PolarisTimingRequest req;
  req.set_address(1);
  req.set_response_column(3);
  v1::Empty e;
  EXPECT_EQ(bad_field(stub_->SetTiming(&ctx, req, &e)), "response_column");
  EXPECT_EQ(state().scan_ns(), 750'000);  // nothing changed
}

// "Make sure that there is no material ... in the detection area" [Polaris manual §7.2]: a
// calibration with a beam interrupted is refused; SW1 held 1 s starts it once the area is
// free; the LEDs of [Polaris manual §5.1, §7.2] follow.
TEST_F(RpcPolarisTest, CalibrationNeedsAFreeAreaAndSw1StartsIt) {
  ASSERT_TRUE(block({3}).ok());
  EXPECT_EQ(state().rx_led(), "red");
  EXPECT_EQ(state().tx_led(), "yellow");
  v1::LineDeviceRequest req;
  req.set_address(1);
  const auto refused = unary(*stub_, &v1::Polaris::Stub::Calibrate, req);
  EXPECT_EQ(refused.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
  EXPECT_NE(refused.error_message().find("beams are interrupted"), std::string::npos)
      << refused.error_message();
  ASSERT_TRUE(block({}).ok());
  const auto sw1 = [this](bool closed) {
    grpc::ClientContext c;
    v1::PolarisSw1Request r;
    r.set_address(1);
    r.set_closed(closed);
    v1::Empty none;
    return stub_->SetSw1(&c, r, &none);
  };
  ASSERT_TRUE(sw1(true).ok());
  (void)exchange(tap_, {}, 1s);
  ASSERT_TRUE(sw1(false).ok());
  const auto s = state();
  EXPECT_TRUE(s.calibrating());
  EXPECT_EQ(s.tx_led(), "yellow-flashing");
  EXPECT_EQ(s.rx_led(), "green");  // the first 5 s
  EXPECT_FALSE(s.manual_adjustment());
  EXPECT_EQ(s.storage(), "none");
  EXPECT_EQ(s.storage_mode(), "temporary");
}

// t_CYCLE from the user, held to [GridScan manual §11]'s band (22 elements: 18..40 ms), for
// the next power-up.
TEST_F(RpcGridScanTest, SetTimingHoldsTheCycleToTheManualsBand) {
  HttpFront h(io_, *server_);
  EXPECT_EQ(state().cycle_ns(), 30'000'000);  // typical, 22 elements
  auto bad = error_of(h.call("rs4sim.v1.GridScan/SetTiming", R"({"address": 0, "cycle_ms": 41})"),
                      400, 3);
  EXPECT_EQ(bad.message(),
            "cycle_ms: t_CYCLE 41 ms outside 18..40 ms for 22 elements [GridScan manual §11]");
  grpc::ClientContext ctx;
  v1::GridScanTimingRequest req;
  req.set_cycle_ms(17);
  v1::Empty e;
  EXPECT_EQ(bad_field(stub_->SetTiming(&ctx, req, &e)), "cycle_ms");
  ASSERT_EQ(h.call("rs4sim.v1.GridScan/SetTiming", R"({"address": 0, "cycle_ms": 40})").status,
            200u);
  EXPECT_EQ(state().cycle_ns(), 30'000'000);  // the running power-up keeps its cycle
  EXPECT_EQ(state().next_cycle_ns(), 40'000'000);
  power_up();
  EXPECT_EQ(state().cycle_ns(), 40'000'000);
}

// The scan cycle and Equation 3's t_response [METRON manual "Slave line mode"] from the user.
TEST_F(RpcMetronTest, SetTimingChangesEquation3sTResponse) {
  HttpFront h(io_, *server_);
  EXPECT_EQ(state().t_response_ms(), 20U);
  EXPECT_EQ(state().scan_cycle_ms(), 10U);
  ASSERT_EQ(h.call("rs4sim.v1.Metron/SetTiming",
                   R"({"address": 5, "scan_cycle_ms": 15, "t_response_ms": 40})")
                .status,
            200u);
  EXPECT_EQ(state().t_response_ms(), 40U);
  EXPECT_EQ(state().scan_cycle_ms(), 15U);
  grpc::ClientContext ctx;
  v1::MetronTimingRequest req;
  req.set_address(5);
  req.set_scan_cycle_ms(10);
  req.set_t_response_ms(2001);
  v1::Empty e;
  EXPECT_EQ(bad_field(stub_->SetTiming(&ctx, req, &e)), "t_response_ms");
  auto bad = error_of(h.call("rs4sim.v1.Metron/SetTiming",
                             R"({"address": 5, "scan_cycle_ms": 0, "t_response_ms": 20})"),
                      400, 3);
  EXPECT_EQ(bad.message(), "scan_cycle_ms: 0 ms outside 1..1000");
  EXPECT_EQ(state().t_response_ms(), 40U);
}

}  // namespace
}  // namespace rs4sim::rpc
