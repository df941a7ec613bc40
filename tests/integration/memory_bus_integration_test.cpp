// Master + 125 generic slaves on the in-memory bus (manual clock): start-up to
// Data_Exch, looped-back data, DPV1 read/write and an alarm round trip.
#include "tests/integration/bus_helpers.h"

#include <gtest/gtest.h>

namespace rs4sim::integration {
namespace {

GenericBusConfig full_bus() {
  GenericBusConfig c;
  c.master_address = 0;
  for (std::uint8_t a = 1; a <= 125; ++a) c.slaves.push_back(slave_config(a));
  return c;
}

std::vector<std::uint8_t> pattern(std::uint8_t a, std::size_t n, std::uint8_t round) {
  std::vector<std::uint8_t> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<std::uint8_t>(a * 7 + i * 13 + round);
  return v;
}

TEST(MemoryBusIntegration, MasterAnd125SlavesExchangeLoopedBackData) {
  GenericBus b(full_bus());
  ASSERT_TRUE(b.run_until([&] { return b.slaves_in_data_exchange() == 125; }, 5s))
      << b.slaves_in_data_exchange() << " of 125 in data exchange";
  for (std::uint8_t round = 1; round <= 2; ++round) {
    for (std::uint8_t a = 1; a <= 125; ++a) {
      const auto out = pattern(a, b.slave(a).device().output_length(), round);
      ASSERT_FALSE(b.master().set_outputs(a, out)) << int(a);
    }
    const auto loops_back = [&] {
      for (std::uint8_t a = 1; a <= 125; ++a) {
        const auto in = b.master().inputs(a);
        const auto want = pattern(a, b.slave(a).device().input_length(), round);
        if (!std::equal(in.begin(), in.end(), want.begin(), want.end())) return false;
      }
      return true;
    };
    ASSERT_TRUE(b.run_until(loops_back, 2s)) << "round " << int(round);
  }
  for (std::uint8_t a = 1; a <= 125; ++a) {
    EXPECT_EQ(b.slave(a).slave().state(), dp::slave::State::kDataExch) << int(a);
    EXPECT_EQ(b.bus().counters(a).malformed, 0U);
  }
  EXPECT_EQ(b.bus().counters(0).malformed, 0U);
}

TEST(MemoryBusIntegration, OnTheWireEveryRequestAfterAReplyStartsTid1AfterIt) {
  // The master hands out its next request together with the reply (Station::send_time()); the
  // bus starts it at reply end + TID1 and adds TSYN before it as for any request. The gaps are
  // measured on what the bus carried: TID1 = 37 bit at 1.5 Mbit/s = 24666.7 ns
  // ([IEC 61158-4-3 bus parameters, timing]).
  GenericBusConfig c;
  c.baud = dp::BaudRate::k1M5;
  c.bus.wire_model = dp::BaudRate::k1M5;
  for (std::uint8_t a = 3; a <= 6; ++a) c.slaves.push_back(slave_config(a));
  GenericBus b(c);
  std::optional<TimePoint> reply_end;
  std::size_t checked = 0, off = 0;
  Duration min_gap = Duration::max(), max_gap = Duration::zero();
  b.bus().add_observer([&](const dp::link::BusEvent& e) {
    const bool request = e.from == c.master_address;
    if (!request) {
      reply_end = e.arrival;
      return;
    }
    if (reply_end) {
      const Duration gap = e.time - *reply_end;
      min_gap = std::min(min_gap, gap);
      max_gap = std::max(max_gap, gap);
      ++checked;
      if (gap < 24'666ns) ++off;
    }
    reply_end.reset();
  });
  ASSERT_TRUE(b.run_until([&] { return b.slaves_in_data_exchange() == 4; }, 5s));
  b.run_for(200ms);  // 20 cycles of 4 Data_Exchanges
  EXPECT_GT(checked, 80U);
  EXPECT_EQ(off, 0U);
  EXPECT_GE(min_gap, 24'666ns);
  EXPECT_LE(min_gap, 24'667ns);  // the request right after a reply: exactly TID1
  EXPECT_GT(max_gap, 1ms);       // and after the last reply of a cycle, the cycle target's wait
}

TEST(MemoryBusIntegration, ThirtySimulatedSecondsRunFastAndStayInDataExchange) {
  GenericBusConfig c;
  for (std::uint8_t a = 2; a <= 11; ++a) c.slaves.push_back(slave_config(a));
  GenericBus b(c);
  const TimePoint t0 = b.clock().now();
  b.run_for(30s);
  EXPECT_EQ(b.clock().now() - t0, 30s);
  EXPECT_EQ(b.slaves_in_data_exchange(), 10U);
  const auto st = b.master().slave_status(5);
  ASSERT_TRUE(st);
  EXPECT_GT(st->counters.data_exchanges, 2000U);  // cycle target 10 ms → ~3000 cycles
  EXPECT_EQ(st->counters.left_data_exchange, 0U);
}

TEST(MemoryBusIntegration, Dpv1WriteReadAndAlarmRoundTrip) {
  GenericBusConfig c;
  c.slaves = {slave_config(5)};
  GenericBus b(c);
  ASSERT_TRUE(b.run_until([&] { return b.slaves_in_data_exchange() == 1; }, 2s));
  const std::vector<std::uint8_t> record = {0xDE, 0xAD, 0xBE, 0xEF};
  auto wid = b.master().write(5, 3, 17, record);
  ASSERT_TRUE(wid);
  ASSERT_TRUE(
      b.run_until([&] { return last_event<dp::master::Dpv1Result>(b.events()) != nullptr; }, 2s));
  const auto* w = last_event<dp::master::Dpv1Result>(b.events());
  EXPECT_EQ(w->id, wid.value());
  EXPECT_FALSE(w->error) << w->error.message();
  b.take_events();
  auto rid = b.master().read(5, 3, 17, 240);
  ASSERT_TRUE(rid);
  ASSERT_TRUE(
      b.run_until([&] { return last_event<dp::master::Dpv1Result>(b.events()) != nullptr; }, 2s));
  const auto* r = last_event<dp::master::Dpv1Result>(b.events());
  EXPECT_FALSE(r->error) << r->error.message();
  EXPECT_EQ(std::vector<std::uint8_t>(r->data.begin(), r->data.end()), record);
  // Unknown record → negative response B0 (invalid index).
  b.take_events();
  ASSERT_TRUE(b.master().read(5, 9, 9, 4));
  ASSERT_TRUE(
      b.run_until([&] { return last_event<dp::master::Dpv1Result>(b.events()) != nullptr; }, 2s));
  const auto* neg = last_event<dp::master::Dpv1Result>(b.events());
  ASSERT_TRUE(neg->negative);
  EXPECT_EQ(dp::pdu::to_wire(neg->negative->error_code_1), 0xB0);
  // Alarm raised by the device: the master sees it in the diagnosis and acknowledges it.
  b.take_events();
  const std::vector<std::uint8_t> user = {0x42};
  ASSERT_FALSE(b.slave(5).device().raise_alarm(2, 0, user));
  ASSERT_TRUE(b.run_until([&] { return !b.slave(5).device().acknowledged_alarms().empty(); }, 2s));
  const auto* alarm = last_event<dp::master::AlarmReceived>(b.events());
  ASSERT_NE(alarm, nullptr);
  EXPECT_EQ(alarm->alarm_type, 2);
  EXPECT_EQ(alarm->data, user);
  EXPECT_EQ(b.slave(5).device().acknowledged_alarms()[0].type, 2);
  EXPECT_EQ(b.slaves_in_data_exchange(), 1U);
}

}  // namespace
}  // namespace rs4sim::integration
