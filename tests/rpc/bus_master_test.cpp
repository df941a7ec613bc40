// rs4sim.v1.BusMaster, the master side's view of its RS4s (`rs4sim master`'s station list):
// our Rs4MasterStation and an RS4 at address 4 on the memory bus, on the manual clock. Known
// answers: the DP start-up reaches data exchange once (Syncs 1) and the F-host runs; one
// dropped reply is one repeat of the request [IEC 61158-4-3 FCB/FCV], the station stays in data
// exchange (Lost 0) — the rule docs/http.md "Station counters" gives for ProfiTrace's columns.
#include "rpc/bus_master_service.h"

#include "dp/link/memory_bus.h"
#include "dp/time/clock.h"
#include "http_front.h"
#include "rpc/executor.h"
#include "rpc/server.h"
#include "rpc/service_support.h"
#include "rs4/device/rs4_device.h"

#include <boost/asio/executor_work_guard.hpp>
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace rs4sim::rpc {
namespace {

using namespace std::chrono_literals;

class InlineExecutor final : public Executor {
 public:
  void run(const std::function<void()>& f) override { f(); }
};

rs4::device::Rs4MasterStationConfig one_rs4() {
  rs4::device::Rs4MasterStationConfig c;
  rs4::device::Rs4MasterOptions o;
  o.address = 4;
  c.slaves.push_back(o);
  c.auto_ack_rei = true;
  return c;
}

rs4::device::Rs4DeviceConfig rs4_at_4() {
  rs4::device::Rs4DeviceConfig c;
  c.switches = rs4::device::switches_for(4);
  c.boot_time = 3000ms;
  return c;
}

// Our master and the RS4 at 4 on the simulated bus, the RS4 powered.
class BusMaster : public ::testing::Test {
 protected:
  BusMaster() {
    bus.attach(station);
    bus.attach(rs4);
    bus.start();
    rs4.power_on(clock.now());
  }
  // One telegram from the RS4 dropped, then 200 ms of the bus: the master repeats.
  void drop_one_from_rs4() {
    dp::link::Fault drop;
    drop.kind = dp::link::FaultKind::kDrop;
    drop.from = 4;
    drop.count = 1;
    bus.inject(drop);
    bus.run_for(200ms);
  }

  dp::ManualClock clock;
  rs4::device::Rs4MasterStation station{one_rs4()};
  rs4::device::Rs4Device rs4{rs4_at_4()};
  dp::link::MemoryBus bus{clock};
};

TEST_F(BusMaster, ListStationsShowsTheMastersViewAndCounters) {
  InlineExecutor executor;
  BusMasterService service(station, clock, executor);
  const auto list = [&] {
    v1::BusStationsResponse out;
    EXPECT_TRUE(service.ListStations(nullptr, nullptr, &out).ok());
    return out;
  };
  const auto before = list();
  ASSERT_EQ(before.stations_size(), 1);
  EXPECT_EQ(before.stations(0).address(), 4U);
  EXPECT_FALSE(before.stations(0).plc().data_exchange());

  std::vector<rs4::device::Rs4MasterEvent> events;  // drained as the run's MasterService does
  ASSERT_TRUE(bus.run_until([&] { return station.in_data_exchange(4); }, clock.now() + 10s,
                            [&] { station.take_events(events); }));
  bus.run_for(5s);  // past the RS4's boot: the F-host in RUN
  const auto s = list().stations(0);
  EXPECT_EQ(s.dp_state(), dp::master::to_string(dp::master::PollState::kDataExchange));
  EXPECT_EQ(s.dp_error(), "");
  EXPECT_TRUE(s.plc().present());
  EXPECT_TRUE(s.plc().data_exchange());
  EXPECT_EQ(s.plc().fhost_state(), "run");
  EXPECT_EQ(s.output_byte() & 0x07U, 1U);  // field pair 1 [RS4 manual §5.1.2]
  EXPECT_EQ(s.plc().dp().syncs(), 1U);
  EXPECT_EQ(s.plc().dp().lost(), 0U);
  EXPECT_EQ(s.plc().dp().repeats(), 0U);
  EXPECT_GT(s.plc().dp().data_exchanges(), 100U);
  EXPECT_EQ(list().now_ns(), to_ns(clock.now()));

  drop_one_from_rs4();
  const auto after = list().stations(0).plc().dp();
  EXPECT_EQ(after.repeats(), 1U);
  EXPECT_EQ(after.lost(), 0U);
  EXPECT_EQ(after.syncs(), 1U);
}

// The same list as JSON over HTTP (docs/http.md), what the page of `rs4sim master` polls: a real
// server in front of the service, the bus on the loop's thread as in a run. The answer is the
// service's own, in the JSON mapping (uint64 counters as strings); what is not the Empty request
// or not a method of BusMaster is refused with the google.rpc.Status of the error.
TEST_F(BusMaster, ListStationsAsJsonOverHttp) {
  boost::asio::io_context io;
  auto work = boost::asio::make_work_guard(io);
  AsioExecutor executor(io);
  std::thread loop([&] { io.run(); });
  {
    BusMasterService service(station, clock, executor);
    RpcServer server(ServerOptions{}, std::vector<grpc::Service*>{&service});
    HttpFront h(io, server);
    executor.run([&] {
      std::vector<rs4::device::Rs4MasterEvent> events;
      ASSERT_TRUE(bus.run_until([&] { return station.in_data_exchange(4); }, clock.now() + 10s,
                                [&] { station.take_events(events); }));
      bus.run_for(5s);
      drop_one_from_rs4();
    });
    const auto a = h.call("rs4sim.v1.BusMaster/ListStations");
    ASSERT_EQ(a.status, 200u) << a.body;
    EXPECT_EQ(a.content_type, "application/json");
    const auto list = from_json<v1::BusStationsResponse>(a.body);
    v1::BusStationsResponse direct;
    ASSERT_TRUE(service.ListStations(nullptr, nullptr, &direct).ok());
    EXPECT_EQ(list.SerializeAsString(), direct.SerializeAsString());
    ASSERT_EQ(list.stations_size(), 1);
    EXPECT_EQ(list.stations(0).address(), 4U);
    EXPECT_EQ(list.stations(0).plc().dp().repeats(), 1U);
    EXPECT_EQ(list.now_ns(), to_ns(clock.now()));
    for (const char* text : {R"("dpState":"DataExchange")", R"("fhostState":"run")",
                             R"("syncs":"1")", R"("repeats":"1")", R"("lost":"0")"}) {
      EXPECT_NE(a.body.find(text), std::string::npos) << text << " in " << a.body;
    }
    auto field = error_of(h.call("rs4sim.v1.BusMaster/ListStations", R"({"address": 4})"), 400, 3);
    EXPECT_NE(field.message().find("address"), std::string::npos) << field.message();
    auto method = error_of(h.call("rs4sim.v1.BusMaster/GetStation", R"({"address": 4})"), 404, 5);
    EXPECT_NE(method.message().find("GetStation"), std::string::npos) << method.message();
    error_of(h.request(boost::beast::http::verb::get, "/api/rs4sim.v1.BusMaster/ListStations"), 405,
             12);
    error_of(h.call("rs4sim.v1.GsdStations/ListStations"), 501, 12);  // not served by this run
  }
  work.reset();
  loop.join();
}

}  // namespace
}  // namespace rs4sim::rpc
