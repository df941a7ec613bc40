// Rs4Device alone and on the bus: address switches ([RS4 manual §4.5]), power, adapter reset 0x94
// ([RS4 manual §5.2.2]).
#include "rs4/device/rs4_device.h"

#include "dp/master/master_error.h"
#include "rs4_fixture.h"

namespace rs4sim::rs4::device::testing {
namespace {

TEST(Rs4DeviceSwitches, SwitchPositionsForAnAddress) {
  EXPECT_EQ(switches_for(4), (adapter::AddressSwitches{0x0, 0x4}));     // factory setting
  EXPECT_EQ(switches_for(0x7E), (adapter::AddressSwitches{0x7, 0xE}));  // 126
  EXPECT_EQ(switches_for(42), (adapter::AddressSwitches{0x2, 0xA}));
}

TEST(Rs4DeviceSwitches, FactoryAddressIsFour) {
  Rs4Device d;
  EXPECT_EQ(d.address(), 4);
  d.power_on(dp::TimePoint{1h});
  EXPECT_EQ(d.address(), 4);
  EXPECT_TRUE(d.on_bus(dp::TimePoint{1h}));
}

TEST(Rs4DeviceSwitches, Bit7IsMasked) {
  Rs4DeviceConfig c;
  c.switches = {0x8, 0xA};  // 0x8A → bit 7 ignored → 0x0A = 10 ([RS4 manual §4.5])
  Rs4Device d(c);
  d.power_on(dp::TimePoint{1h});
  EXPECT_EQ(d.address(), 10);
  EXPECT_TRUE(d.on_bus(dp::TimePoint{1h}));
}

TEST(Rs4DeviceSwitches, ReservedAddressesKeepTheStationSilent) {
  for (const auto sw : {adapter::AddressSwitches{0x7, 0xF}, adapter::AddressSwitches{0xF, 0xF}}) {
    Rs4DeviceConfig c;
    c.switches = sw;  // 127 / 255 must not be used ([RS4 manual §4.5])
    Rs4Device d(c);
    d.power_on(dp::TimePoint{1h});
    EXPECT_FALSE(d.on_bus(dp::TimePoint{1h}));
    EXPECT_EQ(d.adapter().led(), adapter::LedState::kSteadyFault);
    EXPECT_FALSE(d.take_transmit().has_value());
  }
}

// Invalid switches: the station stays silent (above) and reports the factory address 4
// ([RS4 manual §4.5]) until a power-up reads a valid one.
TEST(Rs4DeviceSwitches, InvalidSwitchesReportTheFactoryAddress) {
  Rs4DeviceConfig c;
  c.switches = {0x7, 0xF};
  Rs4Device d(c);
  EXPECT_EQ(d.address(), 4);
  d.power_on(dp::TimePoint{1h});
  EXPECT_EQ(d.address(), 4);
  d.set_address_switches(switches_for(12));
  d.power_cycle(dp::TimePoint{1h + 1s});
  EXPECT_EQ(d.address(), 12);
  EXPECT_TRUE(d.on_bus(dp::TimePoint{1h + 1s}));
}

// The device keeps one dp::slave::Slave (the adapter holds its SlaveControl&): a power-up at a
// new address restarts it in Wait_Prm instead of building another one.
TEST(Rs4DeviceSwitches, OneSlaveForTheDevicesLifetime) {
  Rs4Device d;
  const dp::slave::Slave* const first = &d.slave();
  d.power_on(dp::TimePoint{1h});
  d.set_address_switches(switches_for(9));
  d.power_cycle(dp::TimePoint{1h + 1s});
  EXPECT_EQ(&d.slave(), first);
  EXPECT_EQ(d.slave().address(), 9);
  EXPECT_EQ(d.slave().state(), dp::slave::State::kWaitPrm);
  EXPECT_EQ(d.slave().master_address(), 0xFF);
}

TEST(Rs4DeviceSwitches, NewSwitchPositionTakesEffectAtPowerUp) {
  Rs4Device d;
  const dp::TimePoint t{1h};
  d.power_on(t);
  d.set_address_switches(switches_for(9));
  EXPECT_EQ(d.address(), 4);  // still the address read at power-up
  d.power_cycle(t + 1s);
  EXPECT_EQ(d.address(), 9);
  EXPECT_EQ(d.counters().power_ups, 2U);
}

TEST(Rs4DevicePower, OffStationIsSilentAndHasNoDeadline) {
  Rs4Device d;
  EXPECT_FALSE(d.powered());
  EXPECT_FALSE(d.next_deadline().has_value());
  EXPECT_FALSE(d.on_bus(dp::TimePoint{1h}));
  d.power_on(dp::TimePoint{1h});
  EXPECT_TRUE(d.next_deadline().has_value());  // adapter init and RS4 boot run
  d.power_off(dp::TimePoint{1h} + 1s);
  EXPECT_FALSE(d.next_deadline().has_value());
  EXPECT_EQ(d.adapter().led(), adapter::LedState::kDark);
}

TEST(Rs4DeviceOnBus, PowerOffLosesTheSlaveAndPowerOnBringsItBack) {
  Rs4Segment s(segment_config());
  s.power_on();
  ASSERT_TRUE(s.run_until([&] { return s.in_data_exchange(); }, 5s));
  s.power_off();
  ASSERT_TRUE(s.run_until([&] { return !s.in_data_exchange(); }, 2s));
  EXPECT_FALSE(events_of<dp::master::SlaveLeftDataExchange>(s).empty());
  EXPECT_GT(s.device().counters().ignored_while_silent, 0U);
  s.power_on();
  EXPECT_TRUE(s.run_until([&] { return s.in_data_exchange(); }, 5s));
}

TEST(Rs4DeviceOnBus, AdapterInitTakesTwoToThreeSecondsBeforeDataExchange) {
  Rs4Segment s(segment_config());
  s.power_on();
  const auto t = time_until(
      s, [&] { return s.in_data_exchange(); }, 5s);
  ASSERT_TRUE(t.has_value());
  EXPECT_GE(*t, 2500ms);  // [RS4 manual §4.4]: LED steady 2–3 s, Set_Prm refused meanwhile
  EXPECT_LE(*t, 3500ms);
}

// PROFI_CMD_RESET ([RS4 manual §5.2.2]): WRITE 94 → link down ≈2 s, then Wait_Prm and a new
// start-up.
TEST(Rs4DeviceOnBus, AdapterResetDropsTheLinkForTwoSeconds) {
  Rs4Segment s(segment_config());
  s.power_on();
  ASSERT_TRUE(s.run_until([&] { return s.in_data_exchange(); }, 5s));
  const std::vector<std::uint8_t> record{
      0x00,        // +0 flow-control byte: the master writes 0 ([RS4 manual §5.2.1])
      0x05,        // +1 block length incl. header
      0xFF, 0xFF,  // +2 block number 0xFFFF = last block
      0x94,        // +4 PROFI_CMD_RESET
  };
  const auto w = s.write_record(record);
  // The WRITE is accepted (short ack) and the adapter resets at once: the master sees
  // the slave leave data exchange before it can poll the Write response.
  ASSERT_TRUE(w.has_value());
  EXPECT_EQ(w->error, dp::master::make_error_code(dp::master::MasterError::kAborted))
      << w->error.message();
  // The reset happened inside the WRITE's exchange: the link is down for 2 s from that moment.
  const auto down_until = s.device().adapter().wants_link_down_until();
  ASSERT_TRUE(down_until.has_value());
  const auto reset_at = *down_until - 2s;
  EXPECT_LE(reset_at, s.now());
  EXPECT_TRUE(s.device().link_down());
  ASSERT_TRUE(s.run_until([&] { return !s.in_data_exchange(); }, 1s));
  const auto back = time_until(
      s, [&] { return s.in_data_exchange(); }, 10s);
  ASSERT_TRUE(back.has_value());
  // Both sides: "ca. 2s unterbrochen" [RS4 manual §5.2.2], and the reset is "wie Power-On Reset":
  // the adapter refuses Set_Prm while it initialises (LED steady 2–3 s [RS4 manual §4.4], 2.5 s
  // in the model), so the link is back 2.5 s after the reset plus the master's start-up
  // (Slave_Diag, Set_Prm, Chk_Cfg, Slave_Diag: a few 10 ms cycles), not later.
  EXPECT_GE(s.now() - reset_at, 2500ms);
  EXPECT_LE(s.now() - reset_at, 2500ms + 100ms);
  EXPECT_EQ(s.device().counters().link_drops, 1U);
  EXPECT_FALSE(s.device().link_down());
  EXPECT_EQ(s.device().adapter().counters().resets, 1U);
}

// Device exchange ([RS4 manual §7.1, §7.2] scenario 4): another unit on the adapter, only while
// off.
TEST(Rs4DeviceExchange, ANewUnitBringsItsIdentityAndFactorySettings) {
  Rs4Device d;
  const dp::TimePoint t{1h};
  d.power_on(t);
  scanner::ScannerConfig unit;
  unit.identity.serial_number = 0x00054321;
  EXPECT_FALSE(d.exchange_scanner(unit)) << "refused while powered";
  EXPECT_EQ(d.scanner().parameters().identity.serial_number, 0x00012345U);

  d.power_off(t);
  ASSERT_TRUE(d.exchange_scanner(unit));
  d.power_on(t + 1s);
  EXPECT_EQ(d.scanner().parameters().identity.serial_number, 0x00054321U);
  EXPECT_TRUE(d.scanner().factory_settings());
  EXPECT_EQ(d.address(), 4) << "the adapter and its switches stay";
}

}  // namespace
}  // namespace rs4sim::rs4::device::testing
