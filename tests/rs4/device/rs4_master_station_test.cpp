// The master side of an RS4 segment (Rs4MasterStation) against two real Rs4Devices at
// addresses 4 and 5 on the memory bus, on the manual clock: data exchange, F-hosts in RUN,
// Proxy-Request after the RS4's boot, the proxy seam (Proxy-Enable, record write/read), and
// the RS4's PROFIsafe diagnosis read from the Slave_Diag ([RS4 manual §5.1, §5.2, §6.3, §7.1]).
#include "rs4/device/rs4_master_station.h"

#include "dp/link/memory_bus.h"
#include "rs4/adapter/cyclic_bytes.h"
#include "rs4/device/rs4_device.h"
#include "rs4/protocol/block.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>

namespace rs4sim::rs4::device {
namespace {

using namespace std::chrono_literals;

Rs4DeviceConfig device_config(std::uint8_t address) {
  Rs4DeviceConfig c;
  c.switches = switches_for(address);
  return c;
}

Rs4MasterStationConfig station_config(std::vector<std::uint8_t> addresses) {
  Rs4MasterStationConfig c;
  for (auto a : addresses) {
    Rs4MasterOptions o;
    o.address = a;
    c.slaves.push_back(o);
  }
  return c;
}

// Master side + RS4s on a memory bus; events collected after every bus step.
class Segment {
 public:
  explicit Segment(const Rs4MasterStationConfig& config) : station(config), bus(clock) {
    bus.attach(station);
    for (auto a : station.slave_addresses()) {
      devices.push_back(std::make_unique<Rs4Device>(device_config(a)));
      bus.attach(*devices.back());
    }
    bus.start();
    for (auto& d : devices) d->power_on(clock.now());
  }
  bool run_until(const std::function<bool()>& done, dp::Duration timeout) {
    return bus.run_until(done, clock.now() + timeout, [this] { station.take_events(events); });
  }
  template <class E>
  std::vector<E> events_of(std::uint8_t address) const {
    std::vector<E> out;
    for (const auto& e : events) {
      const auto* x = std::get_if<E>(&e);
      if (x != nullptr && x->address == address) out.push_back(*x);
    }
    return out;
  }

  dp::ManualClock clock;
  Rs4MasterStation station;
  dp::link::MemoryBus bus;
  std::vector<std::unique_ptr<Rs4Device>> devices;
  std::vector<Rs4MasterEvent> events;
};

TEST(Rs4MasterStation, TwoRs4sReachDataExchangeRunAndAskForTheProxyAfterBoot) {
  Segment s(station_config({4, 5}));
  ASSERT_TRUE(s.run_until(
      [&] { return s.station.in_data_exchange(4) && s.station.in_data_exchange(5); }, 5s));
  ASSERT_TRUE(s.run_until(
      [&] {
        return s.station.view(4)->safety == profisafe::FHostState::kRun &&
               s.station.view(5)->safety == profisafe::FHostState::kRun;
      },
      1s));
  // Booting: no Proxy-Request yet, no OSSD ([RS4 manual §5.1.1, §7.1]).
  EXPECT_EQ(s.station.input_byte(4) & adapter::kInputOssd, 0);
  EXPECT_EQ(s.station.input_byte(4) & adapter::kInputProxyRequest, 0);
  const auto asks = [&](std::uint8_t a) {
    return (s.station.input_byte(a) & adapter::kInputProxyRequest) != 0;
  };
  ASSERT_TRUE(s.run_until([&] { return asks(4) && asks(5); }, 31s));
  EXPECT_GE(s.clock.now().time_since_epoch(), 29s);  // after the ≈30 s boot [RS4 manual §7.1.1]
  for (const std::uint8_t a : {std::uint8_t{4}, std::uint8_t{5}}) {
    SCOPED_TRACE(int(a));
    const auto dp = s.events_of<DpStateChanged>(a);
    ASSERT_FALSE(dp.empty());
    EXPECT_EQ(dp.back().state, dp::master::PollState::kDataExchange);
    const auto safety = s.events_of<SafetyStateChanged>(a);
    ASSERT_FALSE(safety.empty());
    EXPECT_EQ(safety.back().state, profisafe::FHostState::kRun);
    const auto inputs = s.events_of<InputByteChanged>(a);
    ASSERT_FALSE(inputs.empty());
    EXPECT_NE(inputs.back().current & adapter::kInputProxyRequest, 0);
    EXPECT_EQ(s.station.view(a)->f_diagnosis, 0);
  }
  // Proxy-Enable 0 (the default): the RS4 releases OSSD without the proxy, but the
  // restart interlock still holds it ([RS4 manual §5.1.2, §7.1]).
  EXPECT_EQ(s.station.input_byte(4) & adapter::kInputOssd, 0);
  EXPECT_EQ(s.devices[0]->adapter().view().proxy_enable, false);
}

TEST(Rs4MasterStation, KeepsTheMastersOwnEventsOnRequest) {
  auto config = station_config({4});
  config.keep_master_events = true;
  Segment s(config);
  ASSERT_TRUE(s.run_until([&] { return s.station.in_data_exchange(4); }, 5s));
  std::vector<dp::master::MasterEvent> raw;
  s.station.take_master_events(raw);
  const auto entered = std::count_if(raw.begin(), raw.end(), [](const auto& e) {
    return std::holds_alternative<dp::master::SlaveEnteredDataExchange>(e);
  });
  EXPECT_EQ(entered, 1);
  raw.clear();
  s.station.take_master_events(raw);
  EXPECT_TRUE(raw.empty());
}

TEST(Rs4MasterStation, UndrainedCycleTicksCollapseIntoTheNewest) {
  Segment s(station_config({4}));
  ASSERT_TRUE(
      s.run_until([&] { return s.station.view(4)->safety == profisafe::FHostState::kRun; }, 5s));
  // The input byte settles: the error bit of the F-host's start-up (0x2418) goes with its
  // going alarm ≥500 ms later [docs/decisions.md#rs4-error-bit].
  s.bus.run_for(1s);
  s.events.clear();
  s.station.take_events(s.events);
  s.events.clear();
  s.bus.run_for(500ms);  // ≈50 cycles, nothing else changes
  s.station.take_events(s.events);
  ASSERT_EQ(s.events.size(), 1U);
  const auto* tick = std::get_if<MasterCycle>(&s.events.front());
  ASSERT_NE(tick, nullptr);
  EXPECT_GE(s.clock.now() - tick->now, 0ms);
  EXPECT_LE(s.clock.now() - tick->now, 10ms);
}

TEST(Rs4MasterStation, ProxyEnableReachesTheRs4AtItsStartup) {
  Segment s(station_config({4}));
  ASSERT_TRUE(s.station.set_proxy_enable(4, true));
  EXPECT_EQ(s.station.view(4)->output_byte, 0x41);  // bit 6 + field pair 1 ([RS4 manual §5.1.2])
  EXPECT_FALSE(s.station.set_proxy_enable(9, true));
  ASSERT_TRUE(s.run_until([&] { return s.devices[0]->adapter().view().proxy_enable; }, 5s));
}

TEST(Rs4MasterStation, RecordWriteAndReadCompleteAsEvents) {
  Segment s(station_config({4}));
  ASSERT_TRUE(s.run_until([&] { return s.station.in_data_exchange(4); }, 5s));
  EXPECT_FALSE(s.station.write_record(9, std::array<std::uint8_t, 1>{0}));  // not configured
  // One block with an RS4 command: COM_CMD_MESS_16_RT-style request of docs/rs4-protocol.md.
  std::vector<std::uint8_t> record;
  const std::array<std::uint8_t, 2> payload{0x00, 0x00};
  ASSERT_FALSE(protocol::encode_block(0x00, protocol::kLastBlockNumber, payload, record));
  const auto wid = s.station.write_record(4, record);
  ASSERT_TRUE(wid);
  const auto done = [&](dp::master::Dpv1RequestId id) {
    for (const auto& e : s.events) {
      const auto* r = std::get_if<RecordResult>(&e);
      if (r != nullptr && r->id == id) return true;
    }
    return false;
  };
  ASSERT_TRUE(s.run_until([&] { return done(wid.value()); }, 2s));
  const auto rid = s.station.read_record(4);
  ASSERT_TRUE(rid);
  ASSERT_TRUE(s.run_until([&] { return done(rid.value()); }, 2s));
  for (const auto& e : s.events) {
    if (const auto* r = std::get_if<RecordResult>(&e)) {
      EXPECT_EQ(r->slot, 0);
      EXPECT_EQ(r->index, 2);
    }
  }
}

TEST(Rs4MasterStation, WrongFDestAddShowsDiagnosis66AndNoDataExchange) {
  auto config = station_config({4});
  config.slaves[0].overrides.push_back({"F_Dest_Add", 505});
  Segment s(config);
  ASSERT_TRUE(s.run_until([&] { return s.station.view(4)->f_diagnosis == 66; }, 5s));
  EXPECT_FALSE(s.station.in_data_exchange(4));
  const auto diag = s.events_of<FDiagnosisChanged>(4);
  ASSERT_FALSE(diag.empty());
  EXPECT_EQ(diag.back().number, 66);  // [RS4 manual §6.3]: wrong F_Dest_Add
}

TEST(Rs4MasterStation, LostRs4PassivatesItsFHost) {
  Segment s(station_config({4, 5}));
  ASSERT_TRUE(
      s.run_until([&] { return s.station.view(5)->safety == profisafe::FHostState::kRun; }, 5s));
  s.devices[1]->power_off(s.clock.now());
  ASSERT_TRUE(
      s.run_until([&] { return s.station.view(5)->safety != profisafe::FHostState::kRun; }, 1s));
  ASSERT_TRUE(s.run_until([&] { return !s.station.in_data_exchange(5); }, 2s));
  EXPECT_EQ(s.station.view(4)->safety, profisafe::FHostState::kRun);  // the other one runs on
  const auto dp = s.events_of<DpStateChanged>(5);
  ASSERT_FALSE(dp.empty());
  EXPECT_TRUE(dp.back().reason) << "a reason for leaving data exchange";
}

TEST(Rs4MasterStation, ConfigurationErrorsAreSpecific) {
  EXPECT_THROW(Rs4MasterStation(Rs4MasterStationConfig{}), std::invalid_argument);
  auto bad = station_config({4});
  bad.slaves[0].overrides.push_back({"No_Such_Parameter", 1});
  EXPECT_THROW(Rs4MasterStation{bad}, std::invalid_argument);
  EXPECT_THROW(Rs4MasterStation{station_config({4, 4})}, std::system_error);
}

// [RS4 manual §6.3]: 6 standard diagnosis bytes, then the status PDU 05 81 00 00 nn.
TEST(Rs4MasterStation, FDiagnosisNumberFromSlaveDiagBytes) {
  const std::array<std::uint8_t, 11> wrong_dest{
      0x00, 0x0C, 0x00, 0x01, 0x53, 0x34,  // Station_Status 1..3, Master_Add, Ident 0x5334
      0x05, 0x81, 0x00, 0x00, 0x42};       // len 5, status message, slot 0, -, 66
  EXPECT_EQ(f_diagnosis_number(wrong_dest), 66);
  const std::array<std::uint8_t, 11> none{0x00, 0x0C, 0x00, 0x01, 0x53, 0x34,
                                          0x05, 0x81, 0x00, 0x00, 0x00};
  EXPECT_EQ(f_diagnosis_number(none), 0);
  const std::array<std::uint8_t, 6> standard_only{0x00, 0x0C, 0x00, 0x01, 0x53, 0x34};
  EXPECT_EQ(f_diagnosis_number(standard_only), std::nullopt);
  const std::array<std::uint8_t, 11> other_block{0x00, 0x0C, 0x00, 0x01, 0x53, 0x34,
                                                 0x05, 0x82, 0x00, 0x00, 0x42};  // not 0x81
  EXPECT_EQ(f_diagnosis_number(other_block), std::nullopt);
  const std::array<std::uint8_t, 10> truncated{0x00, 0x0C, 0x00, 0x01, 0x53,
                                               0x34, 0x05, 0x81, 0x00, 0x00};
  EXPECT_EQ(f_diagnosis_number(truncated), std::nullopt);
}

}  // namespace
}  // namespace rs4sim::rs4::device
