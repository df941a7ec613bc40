// rs4sim.v1.GsdStations (gsd.proto) end to end: a real gRPC server on loopback in front of a GSD
// station on the simulated bus with our master configured from the same GSD (app/devices/
// gsd_segment.h), the loop on its own thread as in a run. The GSD is the project's own
// tests/gsd/corpus/modular_dpv1.gsd: "DI 8" (Cfg 0x10: 1 input byte), "AI 2" (0x51: 2 input
// words = 4 bytes), "DO 16 consistent" (0xA1: 2 output bytes) [IEC 61158-6-3 Chk_Cfg/Get_Cfg].
#include "app/devices/gsd_segment.h"
#include "google/rpc/error_details.pb.h"
#include "google/rpc/status.pb.h"
#include "http_front.h"
#include "rpc/executor.h"
#include "rpc/gsd_service.h"
#include "rpc/server.h"
#include "rpc_calls.h"
#include "rs4sim/v1/gsd.grpc.pb.h"
#include "rs4sim/v1/rs4.grpc.pb.h"
#include "test_loop.h"

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>
#include <gtest/gtest.h>

#include <grpcpp/create_channel.h>
#include <grpcpp/security/credentials.h>

#include <memory>
#include <optional>
#include <thread>

namespace rs4sim::app {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;
using rpc::GsdServiceContext;
using rpc::GsdStationsService;
using rpc::precondition;
// The BadRequest violation as "field: description".
constexpr auto& bad_field = rpc::bad_field_described;

std::string bytes(const Bytes& b) { return {b.begin(), b.end()}; }

// One telegram on the simulated bus as an observer saw it (dp::link::BusEvent, copied out).
struct Seen {
  dp::TimePoint time;
  std::uint8_t from = 0;
  std::optional<std::uint8_t> to;
  Bytes wire;
  dp::link::Fate fate = dp::link::Fate::kDelivered;
};

class RpcGsdTest : public ::testing::Test, protected rpc::TestLoop {
 protected:
  void SetUp() override {
    std::vector<GsdStationSpec> specs;
    specs.push_back(load_gsd_station(std::string(RS4SIM_GSD_CORPUS) + "/modular_dpv1.gsd",
                                     {"DI 8", "AI 2", "DO 16 consistent"}, 5));
    segment_ = std::make_unique<GsdSegment>(std::move(specs), "12M");
    service_ = std::make_unique<GsdStationsService>(GsdServiceContext{
        executor_, {segment_->stations().front().get()}, {}, segment_->bus()});
    start_loop();
    server_ = std::make_unique<rpc::RpcServer>(rpc::ServerOptions{},
                                               std::vector<grpc::Service*>{service_.get()});
    stub_ = v1::GsdStations::NewStub(
        grpc::CreateChannel(server_->address(), grpc::InsecureChannelCredentials()));
  }
  void TearDown() override {
    server_->shutdown();
    stop_loop();
  }
  void run_for(dp::Duration d) {
    executor_.run([&] { segment_->run_for(d); });
  }
  bool master_exchanges() {
    bool in = false;
    executor_.run([&] {
      in = segment_->master().poll_state(5) == dp::master::PollState::kDataExchange;
    });
    return in;
  }
  // The inputs of the station at `address` as the master has them.
  Bytes master_inputs(std::uint8_t address) {
    Bytes inputs;
    executor_.run([&] {
      const auto in = segment_->master().inputs(address);
      inputs.assign(in.begin(), in.end());
    });
    return inputs;
  }
  v1::GsdStation get(std::uint32_t address, grpc::Status* status = nullptr) {
    grpc::ClientContext ctx;
    v1::StationRequest in;
    in.set_address(address);
    v1::GsdStation out;
    const auto s = stub_->GetStation(&ctx, in, &out);
    if (status != nullptr) *status = s;
    return out;
  }
  grpc::Status set_inputs(std::uint32_t address, std::uint32_t slot, const Bytes& data) {
    grpc::ClientContext ctx;
    v1::SetGsdInputsRequest in;
    in.set_address(address);
    in.set_slot(slot);
    in.set_data(bytes(data));
    v1::Empty out;
    return stub_->SetInputs(&ctx, in, &out);
  }
  grpc::Status set_online(bool online) {
    grpc::ClientContext ctx;
    v1::SetGsdOnlineRequest in;
    in.set_address(5);
    in.set_online(online);
    v1::Empty out;
    return stub_->SetOnline(&ctx, in, &out);
  }
  grpc::Status alarm(v1::GsdAlarmType type) {
    grpc::ClientContext ctx;
    v1::RaiseGsdAlarmRequest in;
    in.set_address(5);
    in.set_type(type);
    in.set_slot(1);
    v1::Empty out;
    return stub_->RaiseAlarm(&ctx, in, &out);
  }

  std::unique_ptr<GsdSegment> segment_;
  std::unique_ptr<GsdStationsService> service_;
  std::unique_ptr<rpc::RpcServer> server_;
  std::unique_ptr<v1::GsdStations::Stub> stub_;
};

TEST_F(RpcGsdTest, ListsTheStationAsItsGsdDescribesIt) {
  grpc::ClientContext ctx;
  v1::ListGsdStationsResponse list;
  ASSERT_TRUE(stub_->ListStations(&ctx, v1::Empty{}, &list).ok());
  ASSERT_EQ(list.stations_size(), 1);
  const auto& s = list.stations(0);
  EXPECT_EQ(s.address(), 5u);
  EXPECT_EQ(s.ident_number(), 0xB756u);
  EXPECT_TRUE(s.dpv1());
  ASSERT_EQ(s.alarms_size(), 2);  // Diagnostic_Alarm_supp = 1, Process_Alarm_supp = 1
  EXPECT_EQ(s.alarms(0), "diagnostic");
  EXPECT_EQ(s.alarms(1), "process");
  ASSERT_EQ(s.modules_size(), 3);
  EXPECT_EQ(s.modules(0).name(), "DI 8");
  EXPECT_EQ(s.modules(0).input_length(), 1u);
  EXPECT_EQ(s.modules(1).input_length(), 4u);
  EXPECT_EQ(s.modules(1).output_length(), 0u);
  EXPECT_EQ(s.modules(2).input_length(), 0u);
  EXPECT_EQ(s.modules(2).output_length(), 2u);
  EXPECT_EQ(s.modules(2).outputs(), bytes({0, 0}));  // nothing written yet
  EXPECT_EQ(s.dp_state(), "Wait_Prm");
  EXPECT_TRUE(s.online());
}

TEST_F(RpcGsdTest, InputsReachTheMasterAndItsOutputsTheStation) {
  run_for(500ms);
  ASSERT_TRUE(master_exchanges());
  EXPECT_EQ(get(5).dp_state(), "Data_Exch");
  ASSERT_TRUE(set_inputs(5, 1, {0x11, 0x22, 0x33, 0x44}).ok());
  ASSERT_TRUE(set_inputs(5, 0, {0xA5}).ok());
  executor_.run([&] { (void)segment_->master().set_outputs(5, Bytes{0xAB, 0xCD}); });
  run_for(100ms);
  EXPECT_EQ(master_inputs(5), (Bytes{0xA5, 0x11, 0x22, 0x33, 0x44}));
  const auto s = get(5);
  EXPECT_EQ(s.modules(1).inputs(), bytes({0x11, 0x22, 0x33, 0x44}));
  EXPECT_EQ(s.modules(2).outputs(), bytes({0xAB, 0xCD}));
  EXPECT_GT(s.data_exchanges(), 0u);
  // The simulated bus times no reply (no turnaround source, as on --link memory): absent.
  EXPECT_FALSE(s.has_link_timing());
}

TEST_F(RpcGsdTest, OffTheBusTheMasterLosesTheStationAndFindsItAgain) {
  run_for(500ms);
  ASSERT_TRUE(master_exchanges());
  ASSERT_TRUE(set_online(false).ok());
  EXPECT_FALSE(get(5).online());
  run_for(300ms);
  EXPECT_FALSE(master_exchanges());
  ASSERT_TRUE(set_online(true).ok());
  run_for(1s);
  EXPECT_TRUE(master_exchanges());
}

TEST_F(RpcGsdTest, RefusesWhatTheGsdDoesNotAllow) {
  grpc::Status s;
  s = set_inputs(5, 1, {0x11, 0x22});
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(s), "data: 2 bytes; module \"AI 2\" (slot 1) has 4 input bytes");
  s = set_inputs(5, 3, {0});
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(s), "slot: slot 3 outside 0..2 (the station's 3 modules)");
  s = set_inputs(9, 0, {0});
  EXPECT_EQ(s.error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_EQ(s.error_message(), "no GSD station at address 9 (this run's GSD stations: 5)");
  s = set_inputs(200, 0, {0});
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  (void)get(7, &s);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::NOT_FOUND);
  // Pull_Plug_Alarm_supp is not in the file.
  s = alarm(v1::GSD_ALARM_TYPE_PULL);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
  EXPECT_NE(s.error_message().find("Pull_Plug_Alarm_supp"), std::string::npos) << s.error_message();
  s = alarm(v1::GSD_ALARM_TYPE_UNSPECIFIED);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  // Declared, but before a DPV1 data exchange the alarms are closed [IEC 61158-6-3 MSAC_C1].
  s = alarm(v1::GSD_ALARM_TYPE_PROCESS);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
  EXPECT_NE(s.error_message().find("cannot send it now"), std::string::npos) << s.error_message();
}

// modular_dpv1.gsd has no Max_Diag_Data_Len: the 6 standard bytes only ([PROFIBUS GSD spec]
// default), so Ext_Diag alone fits and a device-related block does not.
TEST_F(RpcGsdTest, DiagnosisWithinMaxDiagDataLen) {
  run_for(500ms);
  grpc::ClientContext ctx;
  v1::SetGsdDiagnosisRequest in;
  in.set_address(5);
  in.set_ext_diag(true);
  v1::Empty out;
  const auto s = stub_->SetDiagnosis(&ctx, in, &out);
  ASSERT_TRUE(s.ok()) << s.error_message() << " " << bad_field(s);
  grpc::ClientContext ctx2;
  // A device-related block: header 0x03 = length 3 incl. the header [IEC 61158-6-3 Slave_Diag].
  in.set_blocks(bytes({0x03, 0x01, 0x02}));
  const auto too_long = stub_->SetDiagnosis(&ctx2, in, &out);
  EXPECT_EQ(too_long.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(too_long),
            "blocks: 3 bytes; the GSD's Max_Diag_Data_Len 6 leaves 0 bytes after the 6 standard "
            "ones");
}

// A DROP of the station's next reply acts on the simulated bus, and only when its clock moves:
// the bus loses exactly that one reply (station 5's `dropped`), our master's slot time expires
// and it repeats the very same request (same bytes, so the same FCB) once
// ([IEC 61158-4-3 FCB/FCV]); the repeat is answered, so no no-answer and the station stays in
// data exchange ([IEC 61158-6-3 slave supervision]). A fault that were a no-op leaves every
// counter as it was. Then the refusals of the Faults service's rules, and ClearBusFaults ends a
// fault that has telegrams left.
TEST_F(RpcGsdTest, BusFaultsByTheFaultsServiceRules) {
  run_for(500ms);
  ASSERT_TRUE(master_exchanges());
  // Shared with the observer, which stays on the bus for the rest of the fixture's life.
  const auto log = std::make_shared<std::vector<Seen>>();
  const std::vector<Seen>& seen = *log;
  executor_.run([&] {
    segment_->bus()->add_observer([log](const dp::link::BusEvent& e) {
      log->push_back({e.time, e.from, e.to, Bytes(e.wire.begin(), e.wire.end()), e.fate});
    });
  });
  struct Counts {
    dp::link::StationCounters bus;
    dp::master::PollCounters poll;
    std::uint64_t slot_timeouts = 0;
    std::uint64_t station_exchanges = 0;
  };
  const auto counts = [&] {
    Counts c;
    executor_.run([&] {
      c.bus = segment_->bus()->counters(5);
      c.poll = segment_->master().slave_status(5)->counters;
      c.slot_timeouts = segment_->master().counters().slot_timeouts;
    });
    c.station_exchanges = get(5).data_exchanges();
    return c;
  };
  const Counts before = counts();
  ASSERT_EQ(before.bus.dropped, 0u);
  ASSERT_EQ(before.poll.retries, 0u);  // a clean bus: nothing repeated yet

  auto in = rpc::bus_fault_request(5, v1::BUS_FAULT_KIND_DROP, v1::DIRECTION_FROM_STATION, 1);
  v1::BusFaultResponse out;
  ASSERT_TRUE(rpc::unary(*stub_, &v1::GsdStations::Stub::InjectBusFault, in, out).ok());
  EXPECT_NE(out.fault_id(), 0u);
  // The clock has not moved: nothing has been dropped yet.
  EXPECT_EQ(counts().bus.dropped, 0u);
  EXPECT_TRUE(seen.empty());

  run_for(50ms);  // five poll cycles of 10 ms
  const Counts after = counts();
  EXPECT_EQ(after.bus.dropped, 1u);                          // exactly one reply lost
  EXPECT_EQ(after.poll.retries, before.poll.retries + 1);    // repeated once
  EXPECT_EQ(after.slot_timeouts, before.slot_timeouts + 1);  // after its slot time
  EXPECT_EQ(after.poll.no_answer, before.poll.no_answer);    // the repeat was answered
  EXPECT_EQ(after.poll.left_data_exchange, before.poll.left_data_exchange);
  EXPECT_TRUE(master_exchanges());
  EXPECT_GT(after.station_exchanges, before.station_exchanges);  // the station answered on

  // On the wire: the one dropped telegram is station 5's reply to our master; the master's
  // requests to 5 just before and just after it are the same bytes (the repeat).
  std::size_t dropped_at = seen.size();
  for (std::size_t i = 0; i < seen.size(); ++i) {
    if (seen[i].fate == dp::link::Fate::kDropped) {
      EXPECT_EQ(dropped_at, seen.size()) << "a second telegram dropped at " << i;
      dropped_at = i;
    }
  }
  ASSERT_LT(dropped_at, seen.size());
  ASSERT_TRUE(dropped_at > 0 && dropped_at + 1 < seen.size());
  const Seen& reply = seen[dropped_at];
  EXPECT_EQ(reply.from, 5u);
  EXPECT_EQ(reply.to, std::optional<std::uint8_t>(segment_->master_address()));
  const Seen& request = seen[dropped_at - 1];
  const Seen& repeat = seen[dropped_at + 1];
  EXPECT_EQ(request.from, segment_->master_address());
  EXPECT_EQ(request.to, std::optional<std::uint8_t>(5));
  EXPECT_EQ(repeat.from, segment_->master_address());
  EXPECT_EQ(repeat.to, std::optional<std::uint8_t>(5));
  EXPECT_EQ(repeat.wire, request.wire);
  EXPECT_EQ(repeat.fate, dp::link::Fate::kDelivered);
  EXPECT_GT(repeat.time, reply.time);  // the master waited out its slot time

  // The Faults service's rules: a count of 0 is refused before anything reaches the bus.
  grpc::ClientContext ctx2;
  in.set_count(0);
  const auto bad = stub_->InjectBusFault(&ctx2, in, &out);
  EXPECT_EQ(bad.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(bad), "count: 0 outside 1..1000000");

  // ClearBusFaults ends a fault with telegrams left: 1000 replies to drop, cleared before the
  // clock moves, drop none.
  grpc::ClientContext ctx3;
  in.set_count(1000);
  ASSERT_TRUE(stub_->InjectBusFault(&ctx3, in, &out).ok());
  grpc::ClientContext ctx4;
  v1::Empty e;
  EXPECT_TRUE(stub_->ClearBusFaults(&ctx4, v1::Empty{}, &e).ok());
  run_for(50ms);
  EXPECT_EQ(counts().bus.dropped, 1u);
  EXPECT_TRUE(master_exchanges());
}

// On a real link (pty, serial, udp) the service has no simulated bus (GsdServiceContext::bus =
// nullptr): both bus-fault calls answer FAILED_PRECONDITION with the reason; a bad request is
// still INVALID_ARGUMENT first (the same checks as on the simulated bus).
TEST_F(RpcGsdTest, BusFaultsOnARealLinkAreRefused) {
  GsdStationsService real(
      GsdServiceContext{executor_, {segment_->stations().front().get()}, {}, nullptr});
  rpc::RpcServer server(rpc::ServerOptions{}, std::vector<grpc::Service*>{&real});
  const auto stub = v1::GsdStations::NewStub(
      grpc::CreateChannel(server.address(), grpc::InsecureChannelCredentials()));
  const std::string reason =
      "LINK bus faults: this run is on a real link; bus faults need the simulated bus "
      "(--link memory)";
  auto in = rpc::bus_fault_request(5, v1::BUS_FAULT_KIND_DROP, v1::DIRECTION_FROM_STATION, 1);
  v1::BusFaultResponse out;
  {
    grpc::ClientContext ctx;
    const auto s = stub->InjectBusFault(&ctx, in, &out);
    EXPECT_EQ(s.error_code(), grpc::StatusCode::FAILED_PRECONDITION) << s.error_message();
    EXPECT_EQ(precondition(s), reason);
    EXPECT_EQ(out.fault_id(), 0u);
  }
  {
    grpc::ClientContext ctx;
    v1::Empty e;
    const auto s = stub->ClearBusFaults(&ctx, v1::Empty{}, &e);
    EXPECT_EQ(s.error_code(), grpc::StatusCode::FAILED_PRECONDITION) << s.error_message();
    EXPECT_EQ(precondition(s), reason);
  }
  {
    grpc::ClientContext ctx;
    in.set_count(0);
    const auto s = stub->InjectBusFault(&ctx, in, &out);
    EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
    EXPECT_EQ(bad_field(s), "count: 0 outside 1..1000000");
  }
  {
    grpc::ClientContext ctx;  // an address no GSD station has: NOT_FOUND, as everywhere
    in.set_count(1);
    in.set_address(9);
    const auto s = stub->InjectBusFault(&ctx, in, &out);
    EXPECT_EQ(s.error_code(), grpc::StatusCode::NOT_FOUND);
  }
  server.shutdown();
}

// The same service as JSON over HTTP (docs/http.md): the answers are the gRPC answers, inputs set
// through POST /api/rs4sim.v1.GsdStations/SetInputs reach our master in the next Data_Exchange,
// and the errors keep their code, message and details. `bytes` are base64 in the JSON mapping:
// "ESIzRA==" is 11 22 33 44, "pQ==" is A5.
TEST_F(RpcGsdTest, JsonOverHttpIsTheSameService) {
  rpc::HttpFront h(io_, *server_);
  const auto list = h.call("rs4sim.v1.GsdStations/ListStations");
  ASSERT_EQ(list.status, 200u) << list.body;
  {
    grpc::ClientContext ctx;
    v1::ListGsdStationsResponse over_grpc;
    ASSERT_TRUE(stub_->ListStations(&ctx, v1::Empty{}, &over_grpc).ok());
    EXPECT_EQ(rpc::from_json<v1::ListGsdStationsResponse>(list.body).SerializeAsString(),
              over_grpc.SerializeAsString());
  }
  EXPECT_NE(list.body.find(R"("identNumber":46934)"), std::string::npos) << list.body;  // 0xB756
  EXPECT_NE(list.body.find(R"("dpState":"Wait_Prm")"), std::string::npos) << list.body;
  EXPECT_NE(list.body.find(R"("name":"DO 16 consistent")"), std::string::npos) << list.body;

  run_for(500ms);
  ASSERT_TRUE(master_exchanges());
  auto a =
      h.call("rs4sim.v1.GsdStations/SetInputs", R"({"address": 5, "slot": 1, "data": "ESIzRA=="})");
  ASSERT_EQ(a.status, 200u) << a.body;
  EXPECT_EQ(a.body, "{}");
  ASSERT_EQ(
      h.call("rs4sim.v1.GsdStations/SetInputs", R"({"address": 5, "slot": 0, "data": "pQ=="})")
          .status,
      200u);
  run_for(100ms);
  EXPECT_EQ(master_inputs(5), (Bytes{0xA5, 0x11, 0x22, 0x33, 0x44}));
  a = h.call("rs4sim.v1.GsdStations/GetStation", R"({"address": 5})");
  ASSERT_EQ(a.status, 200u) << a.body;
  const auto s = rpc::from_json<v1::GsdStation>(a.body);
  EXPECT_EQ(s.dp_state(), "Data_Exch");
  EXPECT_EQ(s.modules(1).inputs(), bytes({0x11, 0x22, 0x33, 0x44}));
  EXPECT_EQ(s.SerializeAsString(), get(5).SerializeAsString());

  // Off the bus and back through JSON.
  ASSERT_EQ(h.call("rs4sim.v1.GsdStations/SetOnline", R"({"address": 5, "online": false})").status,
            200u);
  EXPECT_FALSE(get(5).online());
  ASSERT_EQ(h.call("rs4sim.v1.GsdStations/SetOnline", R"({"address": 5, "online": true})").status,
            200u);
  EXPECT_TRUE(get(5).online());

  // The errors: the gRPC code, its HTTP status and the service's own message and details.
  auto unknown = rpc::error_of(
      h.call("rs4sim.v1.GsdStations/SetInputs", R"({"address": 9, "slot": 0, "data": "AA=="})"),
      404, 5);
  EXPECT_EQ(unknown.message(), "no GSD station at address 9 (this run's GSD stations: 5)");
  rpc::error_of(h.call("rs4sim.v1.GsdStations/GetStation", R"({"address": 7})"), 404, 5);
  auto length = rpc::error_of(
      h.call("rs4sim.v1.GsdStations/SetInputs", R"({"address": 5, "slot": 1, "data": "ESI="})"),
      400, 3);
  ASSERT_EQ(length.details_size(), 1);
  google::rpc::BadRequest bad;
  ASSERT_TRUE(length.details(0).UnpackTo(&bad));
  ASSERT_EQ(bad.field_violations_size(), 1);
  EXPECT_EQ(bad.field_violations(0).field(), "data");
  EXPECT_EQ(bad.field_violations(0).description(),
            "2 bytes; module \"AI 2\" (slot 1) has 4 input bytes");
  EXPECT_NE(length.details(0).type_url().find("google.rpc.BadRequest"), std::string::npos);
  auto pull = rpc::error_of(h.call("rs4sim.v1.GsdStations/RaiseAlarm",
                                   R"({"address": 5, "type": "GSD_ALARM_TYPE_PULL", "slot": 1})"),
                            412, 9);
  EXPECT_NE(pull.message().find("Pull_Plug_Alarm_supp"), std::string::npos) << pull.message();
  // Not the input message in the JSON mapping: protobuf's reason, nothing reaches the station.
  rpc::error_of(
      h.call("rs4sim.v1.GsdStations/SetInputs", R"({"address": 5, "slot": 0, "data": 165})"), 400,
      3);
  rpc::error_of(
      h.call("rs4sim.v1.GsdStations/SetOnline", R"({"address": "five", "online": false})"), 400, 3);
  EXPECT_TRUE(get(5).online());
  rpc::error_of(h.call("rs4sim.v1.GsdStations/SetInput", "{}"), 404, 5);
}

// `rs4sim run --device generic --gsd … --link memory --grpc`: the segment's own services
// (GsdSegment::services) drive it on its manual clock. SimTime moves the clock and nothing else
// does; GsdStations sees the station reach data exchange and its inputs reach our master; the
// RS4 calls name what the run is.
TEST(RpcGsdSegment, TheSegmentsOwnServicesDriveItOnItsClock) {
  std::vector<GsdStationSpec> specs;
  specs.push_back(load_gsd_station(std::string(RS4SIM_GSD_CORPUS) + "/modular_dpv1.gsd",
                                   {"DI 8", "AI 2", "DO 16 consistent"}, 5));
  GsdSegment segment(std::move(specs), "12M");
  boost::asio::io_context io;
  auto work = boost::asio::make_work_guard(io);
  rpc::AsioExecutor executor{io};
  dp::RealClock wall;
  const ServiceList services = segment.services(ServiceContext{executor, io, wall});
  std::vector<grpc::Service*> raw;
  for (const auto& s : services) raw.push_back(s.get());
  std::thread loop([&] { io.run(); });
  {
    rpc::RpcServer server(rpc::ServerOptions{}, raw);
    const auto channel = grpc::CreateChannel(server.address(), grpc::InsecureChannelCredentials());
    const auto gsd = v1::GsdStations::NewStub(channel);
    const auto time = v1::SimTime::NewStub(channel);
    const auto observation = v1::Observation::NewStub(channel);
    const auto now = [&] {
      grpc::ClientContext ctx;
      v1::TimeResponse t;
      EXPECT_TRUE(time->Now(&ctx, v1::Empty{}, &t).ok());
      EXPECT_TRUE(t.simulated());
      return t.now_ns();
    };
    const auto advance = [&](std::uint64_t ms) {
      grpc::ClientContext ctx;
      v1::AdvanceRequest in;
      in.set_duration_ms(ms);
      v1::TimeResponse t;
      EXPECT_TRUE(time->Advance(&ctx, in, &t).ok());
      return t.now_ns();
    };
    const auto station = [&] {
      grpc::ClientContext ctx;
      v1::StationRequest in;
      in.set_address(5);
      v1::GsdStation out;
      EXPECT_TRUE(gsd->GetStation(&ctx, in, &out).ok());
      return out;
    };
    const std::int64_t t0 = now();
    EXPECT_EQ(station().dp_state(), "Wait_Prm");  // the clock has not moved
    EXPECT_EQ(now(), t0);
    EXPECT_EQ(advance(500), t0 + 500'000'000);
    EXPECT_EQ(station().dp_state(), "Data_Exch");
    {
      grpc::ClientContext ctx;
      v1::SetGsdInputsRequest in;
      in.set_address(5);
      in.set_slot(1);
      in.set_data(bytes({0x11, 0x22, 0x33, 0x44}));
      v1::Empty e;
      ASSERT_TRUE(gsd->SetInputs(&ctx, in, &e).ok());
    }
    Bytes before;
    executor.run([&] {
      const auto in = segment.master().inputs(5);
      before.assign(in.begin(), in.end());
    });
    EXPECT_EQ(before, (Bytes{0x00, 0x00, 0x00, 0x00, 0x00}));  // not yet polled
    (void)advance(50);
    Bytes after;
    executor.run([&] {
      const auto in = segment.master().inputs(5);
      after.assign(in.begin(), in.end());
    });
    EXPECT_EQ(after, (Bytes{0x00, 0x11, 0x22, 0x33, 0x44}));
    {
      grpc::ClientContext ctx;
      v1::StationRequest in;
      in.set_address(5);
      v1::DeviceState out;
      const auto s = observation->GetState(&ctx, in, &out);
      EXPECT_EQ(s.error_code(), grpc::StatusCode::FAILED_PRECONDITION) << s.error_message();
    }
    server.shutdown();
  }
  work.reset();
  loop.join();
}

}  // namespace
}  // namespace rs4sim::app
