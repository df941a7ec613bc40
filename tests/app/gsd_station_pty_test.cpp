// A GSD station and our master configured from the same GSD file, in one process over a
// pseudo-terminal pair with the real clock (gsd/station/gsd_station.h): start-up to Data_Exch,
// inputs set per module on the station arrive at the master, the master's outputs at the
// station. Waits are bounded and end as soon as the condition holds.
#include "app/devices/gsd_station_file.h"
#include "dp/link/profibus_line.h"
#include "dp/link/station_runner.h"
#include "dp/master/master.h"
#include "rpc/gsd_service.h"
#include "stream/pty.h"
#include "stream/serial_transport.h"

#include <gtest/gtest.h>

#include <functional>

namespace rs4sim::app {
namespace {

namespace asio = boost::asio;
using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;
using rpc::GsdServiceContext;
using rpc::GsdStationsService;

// The test's loop is this thread: the service's work runs at once.
class InlineExecutor final : public rpc::Executor {
 public:
  void run(const std::function<void()>& f) override { f(); }
};

TEST(GsdStationPty, MasterFromTheSameGsdReachesDataExchangeAndIoArrivesBothWays) {
  const std::string gse = std::string(RS4SIM_GSD_CORPUS) + "/gateway_asi.gse";
  GsdStation station(load_gsd_station(gse, {"Digital 4 byte in/out", "Analog 2 words in"}, 5));
  check_gsd_baud(station.spec(), "19.2k");
  // Generous timing for a loaded machine: 19.2 kbit/s with a slot time far above the
  // GSD's MaxTsdr (60 Tbit) ([IEC 61158-4-3 bus parameters, timing]).
  dp::master::MasterConfig m;
  m.address = 2;
  m.bus = dp::master::BusParameters::defaults_for(dp::BaudRate::k19k2);
  m.bus.tsl = 16000;
  m.claim_token = false;
  m.cycle_target = 20ms;
  m.slaves.push_back(gsd_master_entry(station.spec(), 2000ms));
  dp::master::Master master(m);

  asio::io_context io;
  stream::PseudoTerminal pty;
  const auto line = dp::link::profibus_line(dp::BaudRate::k19k2);
  stream::SerialTransport slave_side(io, pty.release_master(), line, "pty");
  stream::SerialTransport master_side(io, pty.slave_path(), line);
  dp::RealClock clock;
  dp::link::StationRunner rs(io, clock, slave_side), rm(io, clock, master_side);
  rs.add(station);
  rm.add(master);
  std::vector<dp::master::MasterEvent> events;
  const auto wait = [&](const std::function<bool()>& done) {
    const auto end = dp::SteadyClock::now() + 20s;
    while (!done() && dp::SteadyClock::now() < end) {
      io.run_for(2ms);
      if (io.stopped()) io.restart();
      master.take_events(events);
    }
    return done();
  };
  rs.start();
  rm.start();
  ASSERT_TRUE(wait([&] { return master.poll_state(5) == dp::master::PollState::kDataExchange; }))
      << "no Data_Exch over the pty; Set_Prm refused: " << station.application().prm_fault();
  ASSERT_FALSE(station.application().set_inputs(0, Bytes{0xDE, 0xAD, 0xBE, 0xEF}));
  ASSERT_FALSE(station.application().set_inputs(1, Bytes{0x00, 0x64, 0xFF, 0x9C}));
  const Bytes expected{0xDE, 0xAD, 0xBE, 0xEF, 0x00, 0x64, 0xFF, 0x9C};
  EXPECT_TRUE(wait([&] {
    const auto in = master.inputs(5);
    return Bytes(in.begin(), in.end()) == expected;
  }));
  ASSERT_FALSE(master.set_outputs(5, Bytes{0x01, 0x02, 0x03, 0x04}));
  EXPECT_TRUE(wait([&] {
    const auto out = station.application().outputs();
    return Bytes(out.begin(), out.end()) == Bytes{0x01, 0x02, 0x03, 0x04};
  }));
  EXPECT_EQ(rm.counters().malformed, 0U);
  EXPECT_EQ(rs.counters().malformed, 0U);

  // GsdStations.GetStation carries the station's turnaround as the runner measured it
  // (dp/link/turnaround.h), with --tsl as given to the run.
  InlineExecutor executor;
  GsdServiceContext context{executor, {&station}};
  context.turnaround = [&rs](std::uint8_t address) { return rs.turnaround(address); };
  context.slot_time_us = 8000;
  GsdStationsService api(std::move(context));
  v1::StationRequest request;
  request.set_address(5);
  v1::GsdStation got;
  ASSERT_TRUE(api.GetStation(nullptr, &request, &got).ok());
  const dp::link::TurnaroundStats& measured = *rs.turnaround(5);
  ASSERT_TRUE(got.has_link_timing());
  const v1::LinkTiming& t = got.link_timing();
  EXPECT_TRUE(t.present());
  EXPECT_GT(t.replies(), 0U);  // Set_Prm, Chk_Cfg, the diagnosis polls, the Data_Exchanges
  EXPECT_EQ(t.replies(), measured.count());
  EXPECT_EQ(t.late(), 0U);
  EXPECT_EQ(t.slot_time_us(), 8000U);
  EXPECT_EQ(t.max_ns(), static_cast<std::uint64_t>(measured.max_ns()));
  EXPECT_GT(t.max_ns(), 0U);
  EXPECT_LE(t.p50_ns(), t.p99_ns());
  EXPECT_LE(t.p99_ns(), t.max_ns());
  std::uint64_t in_histogram = 0;
  for (const auto& b : t.histogram()) in_histogram += b.count();
  EXPECT_EQ(in_histogram, t.replies());
  v1::ListGsdStationsResponse list;
  ASSERT_TRUE(api.ListStations(nullptr, nullptr, &list).ok());
  ASSERT_EQ(list.stations_size(), 1);
  EXPECT_EQ(list.stations(0).link_timing().replies(), t.replies());
  rm.stop();
  rs.stop();
}

}  // namespace
}  // namespace rs4sim::app
