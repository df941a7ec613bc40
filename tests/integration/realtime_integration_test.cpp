// Our master and a generic slave in one process over a pseudo-terminal pair created in
// the test, and over UDP on localhost, with the real clock: start-up to Data_Exch,
// looped-back data, DPV1 write/read and an alarm round trip. Waits are bounded and end as
// soon as the condition holds.
#include "dp/devices/generic_master_config.h"
#include "dp/link/profibus_line.h"
#include "dp/link/station_runner.h"
#include "dp/master/master.h"
#include "stream/pty.h"
#include "stream/serial_transport.h"
#include "stream/udp_transport.h"
#include "tests/integration/bus_helpers.h"

#include <gtest/gtest.h>

namespace rs4sim::integration {
namespace {

namespace asio = boost::asio;
namespace link = dp::link;

// Generous FDL timing for a loaded machine: 9.6 kbit/s parameters with the largest slot
// time [IEC 61158-4-3 bus parameters, timing] allows (16383 bit ≈ 1.7 s).
dp::master::MasterConfig realtime_master(const GenericSlaveConfig& s) {
  dp::master::MasterConfig m;
  m.address = 2;
  m.bus = dp::master::BusParameters::defaults_for(dp::BaudRate::k9k6);
  m.bus.tsl = 16000;
  m.claim_token = false;  // TTO = TSL·(6+2·TS) would be 16.7 s at this slot time
                          // ([IEC 61158-4-3 bus parameters, timing])
  m.cycle_target = 20ms;
  m.slaves.push_back(dp::devices::master_entry_for(s, 2000ms));
  return m;
}

using TransportPair =
    std::pair<std::unique_ptr<stream::Transport>, std::unique_ptr<stream::Transport>>;

class RealtimeScenario {
 public:
  // `make` builds the master-side and the slave-side transport on the scenario's io_context.
  explicit RealtimeScenario(const std::function<TransportPair(asio::io_context&)>& make)
      : transports_(make(io)),
        master_(realtime_master(kSlave)),
        rm_(io, clock_, *transports_.first),
        rs_(io, clock_, *transports_.second) {
    rm_.add(master_);
    rs_.add(slave_);
  }
  ~RealtimeScenario() {
    rm_.stop();
    rs_.stop();
  }
  void start() {
    rs_.start();
    rm_.start();
  }
  bool wait(const std::function<bool()>& done, Duration timeout = 20s) {
    const auto end = dp::SteadyClock::now() + timeout;
    while (!done() && dp::SteadyClock::now() < end) {
      io.run_for(2ms);
      if (io.stopped()) io.restart();
      master_.take_events(events);
    }
    return done();
  }
  bool in_dx() const {
    const auto st = master_.slave_status(5);
    return st && st->state == dp::master::PollState::kDataExchange;
  }
  // The full scenario of both real-time tests.
  void run() {
    start();
    ASSERT_TRUE(wait([&] { return in_dx(); })) << "no Data_Exch over the link";
    const std::vector<std::uint8_t> out = {0x12, 0x34};
    ASSERT_FALSE(master_.set_outputs(5, out));
    ASSERT_TRUE(wait([&] {
      const auto in = master_.inputs(5);
      return std::equal(in.begin(), in.end(), out.begin(), out.end());
    }));
    const std::vector<std::uint8_t> rec = {1, 2, 3, 4, 5};
    ASSERT_TRUE(master_.write(5, 1, 2, rec));
    ASSERT_TRUE(wait([&] { return last_event<dp::master::Dpv1Result>(events); }));
    EXPECT_FALSE(last_event<dp::master::Dpv1Result>(events)->error);
    events.clear();
    ASSERT_TRUE(master_.read(5, 1, 2, 100));
    ASSERT_TRUE(wait([&] { return last_event<dp::master::Dpv1Result>(events); }));
    const auto* r = last_event<dp::master::Dpv1Result>(events);
    EXPECT_FALSE(r->error) << r->error.message();
    EXPECT_EQ(std::vector<std::uint8_t>(r->data.begin(), r->data.end()), rec);
    const std::vector<std::uint8_t> user = {0x77};
    ASSERT_FALSE(slave_.device().raise_alarm(2, 0, user));
    ASSERT_TRUE(wait([&] { return !slave_.device().acknowledged_alarms().empty(); }));
    EXPECT_NE(last_event<dp::master::AlarmReceived>(events), nullptr);
    EXPECT_EQ(rm_.counters().malformed, 0U);
    EXPECT_EQ(rs_.counters().malformed, 0U);
  }

  std::vector<dp::master::MasterEvent> events;

 private:
  asio::io_context io;
  TransportPair transports_;
  static inline const GenericSlaveConfig kSlave{5, 0x0B0B, {0x31}, true};  // 2 in, 2 out
  dp::RealClock clock_;
  dp::master::Master master_;
  dp::devices::GenericSlave slave_{kSlave};
  link::StationRunner rm_, rs_;
};

TEST(RealtimeIntegration, MasterAndSlaveOverAPtyPair) {
  stream::PseudoTerminal pty;
  RealtimeScenario scenario([&](asio::io_context& io) {
    TransportPair p;
    p.second = std::make_unique<stream::SerialTransport>(
        io, pty.release_master(), link::profibus_line(dp::BaudRate::k9k6), "pty");
    p.first = std::make_unique<stream::SerialTransport>(io, pty.slave_path(),
                                                        link::profibus_line(dp::BaudRate::k9k6));
    return p;
  });
  scenario.run();
}

TEST(RealtimeIntegration, MasterAndSlaveOverUdpOnLocalhost) {
  RealtimeScenario scenario([](asio::io_context& io) {
    const asio::ip::udp::endpoint any{asio::ip::make_address("127.0.0.1"), 0};
    auto m = std::make_unique<stream::UdpTransport>(io, any, any);
    auto s = std::make_unique<stream::UdpTransport>(io, any, m->local_endpoint());
    m->set_peer(s->local_endpoint());
    return TransportPair{std::move(m), std::move(s)};
  });
  scenario.run();
}

}  // namespace
}  // namespace rs4sim::integration
