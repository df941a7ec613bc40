// Cyclic bytes through the adapter with real FHost PDUs ([RS4 manual §5.1, §5.1.2];
// [RS4 manual §5.1]): field pair errors and the 500 ms release, restart timing, field bits.
#include "adapter_rig.h"
#include "rs4/protocol/adapter_error.h"

namespace rs4sim::rs4::adapter::testing {
namespace {

struct Running : ::testing::Test {
  Rig rig;
  void SetUp() override { ASSERT_TRUE(rig.boot_and_release()); }
};

TEST_F(Running, InvalidFieldPairGives2600AndOssd0ThenReleaseAfter500ms) {
  rig.out_byte = 0x05;  // bits 2..0 = 101: no field pair
  rig.run(100ms);
  EXPECT_FALSE(rig.ossd());
  EXPECT_TRUE(rig.host_input() & kInputError);
  const auto last = rig.adapter.error_memory().last_error();
  EXPECT_EQ(last.uc2_error, 0x2600);
  EXPECT_EQ(last.uc1_error, 0x2600);
  EXPECT_EQ(last.uc2_count, 1);
  EXPECT_EQ(rig.adapter.scanner().status().first_pair, 1);  // not forwarded to the RS4
  rig.out_byte = 0x02;                                      // field pair 2 valid again
  rig.run(400ms);
  EXPECT_FALSE(rig.ossd());  // < 500 ms
  EXPECT_FALSE(rig.host_input() & kInputError);
  rig.run(200ms);
  EXPECT_TRUE(rig.ossd());  // ≥ 500 ms after the valid number
  EXPECT_EQ(rig.adapter.scanner().status().first_pair, 2);
}

TEST_F(Running, FieldPairZeroAndSevenAreErrorsToo) {
  for (std::uint8_t bad : {std::uint8_t{0x00}, std::uint8_t{0x06}, std::uint8_t{0x07}}) {
    rig.out_byte = bad;
    rig.run(60ms);
    EXPECT_FALSE(rig.ossd()) << int(bad);
    rig.out_byte = 0x01;
    rig.run(600ms);
    EXPECT_TRUE(rig.ossd()) << int(bad);
  }
  EXPECT_EQ(rig.adapter.error_memory().count(Processor::kUc2, 0x2600), 3);
  EXPECT_EQ(rig.adapter.counters().field_pair_errors, 3u);
}

TEST_F(Running, SwitchingDirectlyBetweenValidPairsKeepsOssd) {
  for (const int pair : {2, 3, 4, 1}) {
    const auto p = static_cast<std::uint8_t>(pair);
    rig.out_byte = p;
    rig.run(100ms);
    EXPECT_TRUE(rig.ossd()) << int(p);
    EXPECT_EQ(rig.adapter.scanner().status().first_pair, p);
  }
}

TEST_F(Running, ProtectiveFieldViolationAndRestartPulseTiming) {
  auto id = rig.adapter.scanner().edit_scene(rig.now).add(scanner::Circle{{500, 0}, 100});
  ASSERT_TRUE(id);
  rig.run(200ms);
  EXPECT_FALSE(rig.ossd());
  EXPECT_TRUE(rig.host_input() & kInputProtectiveField);
  EXPECT_TRUE(rig.host_input() & kInputWarningField);
  ASSERT_TRUE(rig.adapter.scanner().edit_scene(rig.now).remove(id.value()));
  rig.run(200ms);
  EXPECT_FALSE(rig.host_input() & kInputProtectiveField);
  EXPECT_FALSE(rig.ossd());  // restart interlock
  rig.restart_pulse(100ms);  // < 0.12 s: ignored
  EXPECT_FALSE(rig.ossd());
  rig.restart_pulse(5200ms);  // > 5 s: ignored
  EXPECT_FALSE(rig.ossd());
  rig.restart_pulse(120ms);  // 0.12 s: accepted
  EXPECT_TRUE(rig.ossd());
}

TEST_F(Running, RestartButtonOnX1WorksLikeTheBit) {
  auto id = rig.adapter.scanner().edit_scene(rig.now).add(scanner::Circle{{500, 0}, 100});
  rig.run(200ms);
  (void)rig.adapter.scanner().edit_scene(rig.now).remove(id.value());
  rig.run(200ms);
  ASSERT_FALSE(rig.ossd());
  rig.adapter.set_restart_button(true, rig.now);
  rig.run(300ms);
  rig.adapter.set_restart_button(false, rig.now);
  rig.run(100ms);
  EXPECT_TRUE(rig.ossd());
}

// The button on X1 held and released on the manual clock, as Device.SetRestartButton drives it
// [RS4 manual §4.3]: "Während der Betätigung der Restart-Taste sind die sicheren Ausgänge OSSD 1
// und OSSD 2 des RS4 abgeschaltet; die Anzeige am Scanner (LED 3) leuchtet rot. Die Dauer des
// Rücksetz-Signals muss zwischen 0,12 und 5 Sekunden betragen." LED3 red and the PLC's OSSD bit
// 0 while held; the interlock is released at the release, and only by a press of 0.12..5 s
// (119 ms and 5001 ms do nothing, 120 ms and 5000 ms release it).
TEST_F(Running, RestartButtonHeldLed3RedAndTheReleaseCountsByTheManualsWindow) {
  const auto hold = [&](std::chrono::milliseconds d) {
    rig.adapter.set_restart_button(true, rig.now);
    EXPECT_TRUE(rig.adapter.restart_button());
    EXPECT_TRUE(rig.adapter.scanner().leds().led3_red);
    rig.run(d / 20ms * 20ms);
    rig.run(d % 20ms, 1ms);
    EXPECT_TRUE(rig.adapter.scanner().leds().led3_red) << "held for " << d.count() << " ms";
    EXPECT_FALSE(rig.ossd()) << "held for " << d.count() << " ms";
    rig.adapter.set_restart_button(false, rig.now);
    EXPECT_FALSE(rig.adapter.scanner().leds().led3_red) << "released";
    rig.run(100ms);
  };
  const auto interlock = [&] {
    auto id = rig.adapter.scanner().edit_scene(rig.now).add(scanner::Circle{{500, 0}, 100});
    ASSERT_TRUE(id);
    rig.run(200ms);
    ASSERT_TRUE(rig.adapter.scanner().edit_scene(rig.now).remove(id.value()));
    rig.run(200ms);
    ASSERT_FALSE(rig.ossd());
    ASSERT_TRUE(rig.adapter.scanner().status().restart_interlock);
  };
  // Held while the OSSD is on: off while held, LED3 red; on again after the release.
  hold(300ms);
  EXPECT_TRUE(rig.ossd());
  interlock();
  hold(119ms);
  EXPECT_FALSE(rig.ossd()) << "119 ms: too short";
  hold(5001ms);
  EXPECT_FALSE(rig.ossd()) << "5001 ms: too long";
  hold(120ms);
  EXPECT_TRUE(rig.ossd()) << "120 ms: the interlock released at the release";
  interlock();
  hold(5000ms);
  EXPECT_TRUE(rig.ossd()) << "5000 ms";
  EXPECT_EQ(rig.adapter.scanner().counters().restart_too_short, 1U);
  EXPECT_EQ(rig.adapter.scanner().counters().restart_too_long, 1U);
}

// A button held across a device exchange holds the new unit's restart input from its power-on:
// LED3 red once it is measuring, the start interlock released only after the release.
TEST_F(Running, RestartButtonHeldAcrossADeviceExchange) {
  rig.adapter.set_restart_button(true, rig.now);
  rig.adapter.power_off(rig.now);
  ASSERT_TRUE(rig.adapter.exchange_scanner(scanner::ScannerConfig{}));
  rig.start();
  rig.run(31s);
  EXPECT_TRUE(rig.adapter.scanner().status().restart_held);
  EXPECT_TRUE(rig.adapter.scanner().leds().led3_red);
  EXPECT_FALSE(rig.ossd());
  rig.adapter.set_restart_button(false, rig.now);  // held far longer than 5 s: no pulse
  rig.run(100ms);
  EXPECT_FALSE(rig.adapter.scanner().leds().led3_red);
  EXPECT_FALSE(rig.ossd());
  rig.restart_pulse(200ms);
  EXPECT_TRUE(rig.ossd());
}

TEST_F(Running, ProxyEnableIsNotEvaluatedDuringOperation) {
  rig.out_byte = 0x41;  // Proxy-Enable 1 now: no effect until start-up / PC removal
  rig.run(200ms);
  EXPECT_FALSE(rig.adapter.view().proxy_enable);
  EXPECT_TRUE(rig.ossd());
}

TEST_F(Running, CrcErrorOfTheHostGives2418AndFailSafe) {
  rig.host.faults().corrupt_crc2 = 1;
  rig.run(40ms);
  EXPECT_EQ(rig.adapter.error_memory().last_error().uc2_error, 0x2418);
  EXPECT_FALSE(rig.ossd());
}

TEST_F(Running, ContaminationWarningClearsInvertedBit6) {
  EXPECT_TRUE(rig.host_input() & kInputWarningOutputN);  // not set → 1
  rig.adapter.scanner().set_contamination(60, rig.now);
  rig.run(200ms);
  EXPECT_FALSE(rig.host_input() & kInputWarningOutputN);  // set → 0 ([RS4 manual §5.1.1] inverted)
  EXPECT_TRUE(rig.ossd());
}

TEST_F(Running, ScannerFaultSetsErrorBitAndOssd0) {
  ASSERT_TRUE(rig.adapter.scanner().inject_fault(scanner::Fault::kMotorSpeed, rig.now));
  rig.run(200ms);
  EXPECT_FALSE(rig.ossd());
  EXPECT_TRUE(rig.host_input() & kInputError);
}

TEST_F(Running, LeavingDataExchangeAndComingBackSelectsPair1) {
  rig.out_byte = 0x03;
  rig.run(100ms);
  rig.adapter.on_state_change(dp::slave::State::kDataExch, dp::slave::State::kWaitPrm,
                              dp::slave::TransitionReason::kWatchdog, rig.now);
  EXPECT_FALSE(rig.adapter.ossd_bit());
  rig.adapter.on_state_change(dp::slave::State::kWaitCfg, dp::slave::State::kDataExch,
                              dp::slave::TransitionReason::kCfgAccepted, rig.now);
  rig.adapter.on_time(rig.now + 100ms);
  EXPECT_EQ(rig.adapter.scanner().status().first_pair, 1);
}

}  // namespace
}  // namespace rs4sim::rs4::adapter::testing
