// rs4sim.v1.BusMaster, the master side's view of its RS4s (`rs4sim master`'s station list):
// our Rs4MasterStation and an RS4 at address 4 on the memory bus, on the manual clock. Known
// answers: the DP start-up reaches data exchange once (Syncs 1) and the F-host runs; one
// dropped reply is one repeat of the request [IEC 61158-4-3 FCB/FCV], the station stays in data
// exchange (Lost 0) — the rule docs/http.md "Station counters" gives for ProfiTrace's columns.
#include "rpc/bus_master_service.h"

#include "dp/link/memory_bus.h"
#include "dp/time/clock.h"
#include "rpc/service_support.h"
#include "rs4/device/rs4_device.h"

#include <gtest/gtest.h>

#include <chrono>

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

TEST(BusMaster, ListStationsShowsTheMastersViewAndCounters) {
  dp::ManualClock clock;
  rs4::device::Rs4MasterStation station(one_rs4());
  rs4::device::Rs4Device rs4(rs4_at_4());
  dp::link::MemoryBus bus(clock);
  bus.attach(station);
  bus.attach(rs4);
  bus.start();
  rs4.power_on(clock.now());
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

  dp::link::Fault drop;
  drop.kind = dp::link::FaultKind::kDrop;
  drop.from = 4;
  drop.count = 1;
  bus.inject(drop);
  bus.run_for(200ms);
  const auto after = list().stations(0).plc().dp();
  EXPECT_EQ(after.repeats(), 1U);
  EXPECT_EQ(after.lost(), 0U);
  EXPECT_EQ(after.syncs(), 1U);
}

}  // namespace
}  // namespace rs4sim::rpc
