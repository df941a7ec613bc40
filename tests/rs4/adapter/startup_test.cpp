// Start-up and operating scenarios of [RS4 manual §7.1, §7.2] ([RS4 manual §7.1, §7.2]) on the
// manual clock: 30 s RS4 boot, Proxy-Enable / Proxy-Request / OSSD release, PC adapter.
#include "adapter_rig.h"

namespace rs4sim::rs4::adapter::testing {
namespace {

TEST(Startup, ProxyEnable0_OssdReleasedAtOnceWhenRs4IsUp) {
  Rig rig;
  rig.start();
  rig.run(5s);
  // RS4 still booting: OSSD 0, operating state bit 4 = 1, no Proxy-Request yet.
  EXPECT_EQ(rig.adapter.proxy_phase(), ProxyPhase::kWaitRs4);
  EXPECT_FALSE(rig.ossd());
  EXPECT_EQ(rig.host_input() & (kInputOperatingState | kInputProxyRequest), kInputOperatingState);
  rig.run(26s);  // ≈30 s after power-on the RS4 is operational
  EXPECT_EQ(rig.adapter.proxy_phase(), ProxyPhase::kRequested);
  EXPECT_TRUE(rig.host_input() & kInputProxyRequest);
  EXPECT_TRUE(rig.adapter.released());  // Proxy-Enable 0: no proxy needed
  EXPECT_FALSE(rig.host_input() & kInputOperatingState);
  EXPECT_FALSE(rig.ossd());  // start interlock: restart pulse first
  rig.restart_pulse(200ms);
  EXPECT_TRUE(rig.ossd());
  EXPECT_TRUE(rig.adapter.ossd_bit());
}

TEST(Startup, BootTakes30Seconds) {
  Rig rig;
  rig.start();   // 3 s after power-on
  rig.run(26s);  // 29 s
  EXPECT_NE(rig.adapter.view().rs4, scanner::ScannerState::kMeasuring);
  EXPECT_EQ(rig.adapter.proxy_phase(), ProxyPhase::kWaitRs4);
  rig.run(1500ms);
  EXPECT_EQ(rig.adapter.view().rs4, scanner::ScannerState::kMeasuring);
}

TEST(Startup, ProxyEnable1_ReleasedOnlyAfterSuccessfulSync) {
  Rig rig;
  rig.out_byte = 0x41;  // Proxy-Enable, field pair 1
  rig.start();
  rig.run(31s);
  rig.restart_pulse();
  EXPECT_TRUE(rig.host_input() & kInputProxyRequest);
  EXPECT_TRUE(rig.host_input() & kInputOperatingState);  // check not done
  EXPECT_FALSE(rig.ossd());
  ASSERT_FALSE(rig.adapter.proxy_sync_started(rig.now));
  rig.run(100ms);
  EXPECT_FALSE(rig.host_input() & kInputProxyRequest);  // reset when the check begins
  EXPECT_EQ(rig.adapter.proxy_phase(), ProxyPhase::kSyncRunning);
  EXPECT_FALSE(rig.ossd());
  ASSERT_FALSE(rig.adapter.proxy_sync_succeeded(rig.now));
  rig.run(100ms);
  EXPECT_EQ(rig.adapter.proxy_phase(), ProxyPhase::kDone);
  EXPECT_TRUE(rig.ossd());
}

TEST(Startup, ProxyEnable1_FailedSyncSetsRequestAgainAndKeepsOssd0) {
  Rig rig;
  rig.out_byte = 0x41;
  rig.start();
  rig.run(31s);
  rig.restart_pulse();
  ASSERT_FALSE(rig.adapter.proxy_sync_started(rig.now));
  ASSERT_FALSE(rig.adapter.proxy_sync_failed(rig.now));
  rig.run(100ms);
  EXPECT_TRUE(rig.host_input() & kInputProxyRequest);
  EXPECT_FALSE(rig.ossd());
  EXPECT_TRUE(rig.adapter.scanner().factory_settings());  // the failure reset the RS4
  // a second, successful attempt releases (after the start interlock's restart pulse: the
  // factory reset restarted the RS4)
  ASSERT_FALSE(rig.adapter.proxy_sync_started(rig.now));
  ASSERT_FALSE(rig.adapter.proxy_sync_succeeded(rig.now));
  rig.restart_pulse();
  EXPECT_TRUE(rig.ossd());
}

TEST(Startup, ProxyHooksRefuseOutOfOrderCalls) {
  Rig rig;
  EXPECT_EQ(rig.adapter.proxy_sync_started(rig.now), AdapterApiError::kPoweredOff);
  rig.start();
  EXPECT_EQ(rig.adapter.proxy_sync_started(rig.now), AdapterApiError::kNoSyncRequested);
  EXPECT_EQ(rig.adapter.proxy_sync_succeeded(rig.now), AdapterApiError::kNoSyncRunning);
  EXPECT_EQ(rig.adapter.proxy_sync_failed(rig.now), AdapterApiError::kNoSyncRunning);
}

TEST(Startup, PcAdapterAttachedAtStartup_NoProxyRequestOssdFollowsRs4) {
  Rig rig;
  rig.out_byte = 0x41;  // even with Proxy-Enable
  rig.adapter.attach_pc_adapter(rig.now);
  rig.start();
  rig.run(31s);
  rig.restart_pulse();
  EXPECT_FALSE(rig.host_input() & kInputProxyRequest);
  EXPECT_TRUE(rig.host_input() & kInputRs232Active);
  EXPECT_TRUE(rig.ossd());
  rig.adapter.detach_pc_adapter(rig.now);  // removal always requests a sync
  rig.run(100ms);
  EXPECT_TRUE(rig.host_input() & kInputProxyRequest);
  EXPECT_FALSE(rig.host_input() & kInputRs232Active);
  EXPECT_TRUE(rig.ossd());  // OSSD unaffected unless the sync fails
  ASSERT_FALSE(rig.adapter.proxy_sync_started(rig.now));
  ASSERT_FALSE(rig.adapter.proxy_sync_failed(rig.now));
  rig.run(100ms);
  EXPECT_FALSE(rig.ossd());  // Proxy-Enable 1 and the sync failed
  EXPECT_TRUE(rig.host_input() & kInputProxyRequest);
}

// [RS4 manual §7.1.2] "Das Proxy-Request-Bit wird nicht gesetzt solange der PC-Adapter
// angeschlossen bleibt … Erst wenn der PC-Adapter abgenommen wird, setzt der PROFIsafe-Adapter das
// Proxy-Request-Bit": a pending bit 2 drops when the PC adapter is attached, stays 0 while it is
// (also when a sync could be asked for: no 98 starts one) and comes back at its removal.
TEST(Startup, PcAdapterAttachedWithdrawsAPendingProxyRequest) {
  Rig rig;
  rig.start();
  rig.run(31s);
  ASSERT_TRUE(rig.host_input() & kInputProxyRequest);
  rig.adapter.attach_pc_adapter(rig.now);
  rig.run(100ms);
  EXPECT_FALSE(rig.host_input() & kInputProxyRequest);
  EXPECT_TRUE(rig.host_input() & kInputRs232Active);
  EXPECT_EQ(rig.adapter.proxy_sync_started(rig.now), AdapterApiError::kNoSyncRequested);
  rig.adapter.power_cycle(rig.now);  // attached through a power cycle: still no request
  rig.start(/*power=*/false);
  rig.run(31s);
  EXPECT_FALSE(rig.host_input() & kInputProxyRequest);
  rig.adapter.detach_pc_adapter(rig.now);
  rig.run(100ms);
  EXPECT_TRUE(rig.host_input() & kInputProxyRequest);
  EXPECT_EQ(rig.adapter.proxy_session().reason(), protocol::SyncReason::kPcAdapterRemoved);
}

// Table 5.1-1 bit 2 "Vor dem ersten sowie während des Parameterabgleichs ist das OSSD-Bit auf 0
// gesetzt" against [RS4 manual §7.1.2] "Beim Abnehmen wird immer der automatische
// Parameterabgleich angefordert. Das OSSD-Bit wird davon nicht beeinflusst solange bei dem
// Parameterabgleich keine Fehler auftreten" [docs/decisions.md#rs4-ossd-during-a-later-sync]: with
// Proxy-Enable 1 the first sync holds bit 7 at 0 and bit 4 at 1 throughout; the sync after the PC
// adapter's removal leaves bit 7 at 1 and bit 4 at 0 throughout (sampled every cycle).
TEST(Startup, FirstSyncHoldsTheOssdBitTheSyncAfterRemovalDoesNot) {
  Rig rig;
  rig.out_byte = 0x41;  // Proxy-Enable 1, field pair 1
  rig.start();
  rig.run(31s);
  ASSERT_FALSE(rig.adapter.proxy_sync_started(rig.now));
  for (int i = 0; i < 100; ++i) {  // 2 s of the first sync
    rig.run(20ms);
    ASSERT_EQ(rig.host_input() & (kInputOssd | kInputOperatingState), kInputOperatingState) << i;
  }
  ASSERT_FALSE(rig.adapter.proxy_sync_succeeded(rig.now));
  rig.restart_pulse();  // the start interlock of the RS4 [RS4 manual §4.3]
  ASSERT_TRUE(rig.ossd());
  rig.adapter.attach_pc_adapter(rig.now);
  rig.run(100ms);
  rig.adapter.detach_pc_adapter(rig.now);
  rig.run(100ms);
  ASSERT_TRUE(rig.host_input() & kInputProxyRequest);
  ASSERT_FALSE(rig.adapter.proxy_sync_started(rig.now));  // the upload of the site's set
  for (int i = 0; i < 100; ++i) {
    rig.run(20ms);
    ASSERT_EQ(rig.host_input() & (kInputOssd | kInputOperatingState | kInputProxyRequest),
              kInputOssd)
        << i;
  }
  ASSERT_FALSE(rig.adapter.proxy_sync_succeeded(rig.now));
  rig.run(100ms);
  EXPECT_TRUE(rig.ossd());
}

TEST(Startup, AttachDuringSyncSwitchesThroughOnlyAfterTheSync) {
  Rig rig;
  rig.start();
  rig.run(31s);
  ASSERT_FALSE(rig.adapter.proxy_sync_started(rig.now));
  rig.adapter.attach_pc_adapter(rig.now);
  rig.run(100ms);
  EXPECT_FALSE(rig.host_input() & kInputRs232Active);
  ASSERT_FALSE(rig.adapter.proxy_sync_succeeded(rig.now));
  rig.run(100ms);
  EXPECT_TRUE(rig.host_input() & kInputRs232Active);
}

TEST(Startup, LedStates) {
  Rig rig;
  EXPECT_EQ(rig.adapter.led(), LedState::kDark);
  rig.adapter.power_on(rig.now);
  rig.advance(2s);
  EXPECT_EQ(rig.adapter.led(), LedState::kSteadyInit);  // steady 2–3 s
  rig.advance(1s);
  EXPECT_EQ(rig.adapter.led(), LedState::kFastBlink);  // ready for PROFIBUS
  rig.start(false);
  EXPECT_EQ(rig.adapter.led(), LedState::kOffConnected);
  rig.adapter.power_off(rig.now);
  rig.adapter.set_address_switches({0x7, 0xF});  // 127: not usable
  rig.adapter.power_on(rig.now);
  EXPECT_FALSE(rig.adapter.station_address());
  rig.advance(5s);
  EXPECT_EQ(rig.adapter.led(), LedState::kSteadyFault);  // steady > 3 s
}

TEST(Startup, SetPrmDuringAdapterInitIsRefusedWithoutStatusPdu) {
  Rig rig;
  rig.adapter.power_on(rig.now);
  rig.advance(1s);
  EXPECT_EQ(rig.adapter.check_parameters(set_prm_for(rig.params), rig.now),
            dp::slave::PrmVerdict::kPrmFault);
  EXPECT_TRUE(rig.control.diagnosis.empty());
}

TEST(Startup, WrongUserPrmShapeAndWrongCfgAreRefused) {
  Rig rig;
  rig.adapter.power_on(rig.now);
  rig.advance(3s);
  auto prm = set_prm_for(rig.params);
  prm.user_data[1] = 0x06;  // structure type 6 instead of 5 (F-parameters)
  EXPECT_EQ(rig.adapter.check_parameters(prm, rig.now), dp::slave::PrmVerdict::kPrmFault);
  prm = set_prm_for(rig.params);
  prm.user_data.pop_back();  // 13 bytes
  EXPECT_EQ(rig.adapter.check_parameters(prm, rig.now), dp::slave::PrmVerdict::kPrmFault);
  const std::array<std::uint8_t, 3> other{0xC0, 0x84, 0x85};
  EXPECT_EQ(rig.adapter.check_config(other, false, rig.now), dp::slave::CfgVerdict::kCfgFault);
  const std::array<std::uint8_t, 2> shorter{0xC0, 0x84};
  EXPECT_EQ(rig.adapter.check_config(shorter, false, rig.now), dp::slave::CfgVerdict::kCfgFault);
}

TEST(Startup, AddressSwitchesSetFDestAddAtPowerOn) {
  Rig rig({}, rs4_fparams(600));
  rig.adapter.set_address_switches({0x6, 0x4});  // 0x64 = 100 → F_Dest_Add 600
  rig.adapter.power_on(rig.now);
  EXPECT_EQ(rig.adapter.station_address(), 100);
  EXPECT_EQ(rig.adapter.view().f_dest_add, 600);
  rig.start(false);
  rig.run(31s);
  rig.restart_pulse();
  EXPECT_TRUE(rig.ossd());
}

TEST(Startup, SafetyLayerFaultGivesFailSafeZero) {
  Rig rig;
  rig.start();
  rig.run(31s);
  rig.restart_pulse();
  ASSERT_TRUE(rig.ossd());
  rig.adapter.safety_faults().mute = true;  // no F-input PDU → host watchdog
  rig.run(1200ms);
  EXPECT_EQ(rig.host_input(), 0);  // passivated: substitute values
}

}  // namespace
}  // namespace rs4sim::rs4::adapter::testing
