// Timing rules of the scanner model, all on a manual clock (docs/rs4-scanner.md).
#include "scanner_test_support.h"

#include <gtest/gtest.h>

namespace rs4sim::rs4::scanner {
namespace {

using namespace testing;

// [RS4 manual §7.1.1]: the RS4 reaches operation after about 30 s (configurable, default 30 s).
TEST(ScannerTiming, BootTakes30SecondsNotLess) {
  ManualTime t;
  Scanner s;
  ASSERT_TRUE(s.set_parameters(params(RestartMode::kAutomatic), t.now));
  s.power_on(t.now);
  EXPECT_EQ(s.status().state, ScannerState::kInitialisation);
  EXPECT_EQ(s.next_deadline(), kT0 + seconds(30));
  s.advance(t.advance(seconds(30) - std::chrono::nanoseconds(1)));
  EXPECT_EQ(s.status().state, ScannerState::kInitialisation);
  EXPECT_FALSE(s.ossd());
  EXPECT_EQ(s.status().scan_counter, 0U);
  s.advance(t.advance(std::chrono::nanoseconds(1)));
  EXPECT_EQ(s.status().state, ScannerState::kMeasuring);
  EXPECT_TRUE(s.ossd());                   // automatic start, free field
  EXPECT_EQ(s.status().scan_counter, 1U);  // first scan at the boot end
  EXPECT_EQ(s.next_deadline(), kT0 + seconds(30) + milliseconds(40));
}

TEST(ScannerTiming, ConfigurableBootDuration) {
  ManualTime t;
  ScannerConfig cfg;
  cfg.boot_duration = milliseconds(500);
  Scanner s(cfg);
  s.power_on(t.now);
  s.advance(t.advance(milliseconds(499)));
  EXPECT_EQ(s.status().state, ScannerState::kInitialisation);
  s.advance(t.advance(milliseconds(1)));
  EXPECT_EQ(s.status().state, ScannerState::kMeasuring);
}

// The OSSDs never switch on while the field is occupied, also not at the first scan.
TEST(ScannerTiming, NoStartOnAnOccupiedField) {
  ManualTime t;
  Scanner s;
  ASSERT_TRUE(s.set_parameters(params(RestartMode::kAutomatic, 3), t.now));
  const auto id = s.edit_scene(t.now).add(intruder());
  s.power_on(t.now);
  s.advance(t.advance(seconds(30)));
  EXPECT_FALSE(s.ossd());
  EXPECT_TRUE(s.status().protective_violated);
  s.advance(t.advance(milliseconds(120)));  // still below k = 5 scans
  EXPECT_FALSE(s.ossd());
  ASSERT_TRUE(s.edit_scene(t.now).remove(id.value()));
  s.advance(t.advance(milliseconds(40)));
  EXPECT_TRUE(s.ossd());
}

// Start interlock: after boot the OSSDs wait for a restart pulse.
TEST(ScannerTiming, StartInterlockWaitsForPulse) {
  ManualTime t;
  Scanner s = booted(params(RestartMode::kStartInterlock), t);
  EXPECT_FALSE(s.ossd());
  EXPECT_TRUE(s.status().restart_interlock);
  s.set_restart_input(true, t.now);
  s.set_restart_input(false, t.advance(milliseconds(300)));
  EXPECT_TRUE(s.ossd());
  EXPECT_FALSE(s.status().restart_interlock);
}

// OSSD model: off at the k-th consecutive violated scan, k = T / 40 ms, T = 80 + n·40 ms.
// The object appears 1 ns after a scan (the worst case): off within T, not before scan k.
TEST(ScannerTiming, OssdOffWithinResponseTimeAndNotBeforeKScans) {
  for (const std::uint8_t n :
       {std::uint8_t{0}, std::uint8_t{1}, std::uint8_t{3}, std::uint8_t{14}}) {
    ManualTime t;
    Scanner s = booted(params(RestartMode::kAutomatic, n), t);
    ASSERT_TRUE(s.ossd());
    const TimePoint entered = t.advance(std::chrono::nanoseconds(1));
    ASSERT_TRUE(s.edit_scene(t.now).add(intruder()));
    const std::uint32_t k = 2U + n;
    for (std::uint32_t scan = 1; scan < k; ++scan) {
      s.advance(kT0 + seconds(30) + milliseconds(40) * scan);
      EXPECT_TRUE(s.ossd()) << "n=" << int{n} << " scan " << scan;
      EXPECT_TRUE(s.status().protective_violated);
    }
    s.advance(kT0 + seconds(30) + milliseconds(40) * k);
    EXPECT_FALSE(s.ossd()) << "n=" << int{n};
    const auto took = s.last_scan().at - entered;
    EXPECT_LE(took, milliseconds(80 + 40 * n));
    EXPECT_GT(took, milliseconds(80 + 40 * n) - milliseconds(40));
  }
}

// A violation seen by fewer than k scans does not switch the OSSDs off.
TEST(ScannerTiming, ShortViolationBelowKScansKeepsOssdOn) {
  ManualTime t;
  Scanner s = booted(params(RestartMode::kAutomatic, 1), t);  // k = 3
  const auto id = s.edit_scene(t.advance(milliseconds(1))).add(intruder());
  ASSERT_TRUE(id);
  s.advance(kT0 + seconds(30) + milliseconds(80));  // 2 violated scans
  EXPECT_TRUE(s.ossd());
  ASSERT_TRUE(s.edit_scene(kT0 + seconds(30) + milliseconds(81)).remove(id.value()));
  s.advance(kT0 + seconds(30) + milliseconds(400));
  EXPECT_TRUE(s.ossd());
  EXPECT_EQ(s.counters().ossd_off_switches, 0U);
}

// Automatic restart: on again at the first free scan.
TEST(ScannerTiming, AutomaticRestartAfterFieldClears) {
  ManualTime t;
  Scanner s = booted(params(RestartMode::kAutomatic), t);
  const auto id = s.edit_scene(t.now).add(intruder());
  s.advance(t.advance(milliseconds(80)));
  ASSERT_FALSE(s.ossd());
  ASSERT_TRUE(s.edit_scene(t.advance(milliseconds(1))).remove(id.value()));
  s.advance(t.advance(milliseconds(38)));
  EXPECT_FALSE(s.ossd());  // no scan yet
  s.advance(t.advance(milliseconds(1)));
  EXPECT_TRUE(s.ossd());
}

// Restart interlock: after a violation the OSSDs stay off until a pulse on a free field.
TEST(ScannerTiming, RestartInterlockNeedsPulseOnFreeField) {
  ManualTime t;
  Scanner s = started(RestartMode::kStartRestartInterlock, t);
  ASSERT_TRUE(s.ossd());
  const auto id = s.edit_scene(t.now).add(intruder());
  s.advance(t.advance(milliseconds(120)));
  ASSERT_FALSE(s.ossd());
  EXPECT_TRUE(s.status().restart_interlock);
  pulse(s, t);  // pulse on an occupied field
  EXPECT_FALSE(s.ossd());
  EXPECT_EQ(s.counters().restart_without_effect, 1U);
  ASSERT_TRUE(s.edit_scene(t.now).remove(id.value()));
  s.advance(t.advance(seconds(2)));
  EXPECT_FALSE(s.ossd());  // free, still interlocked
  pulse(s, t);
  EXPECT_TRUE(s.ossd());
}

// Start interlock only: after a violation the OSSDs come back without a pulse.
TEST(ScannerTiming, StartInterlockModeRestartsAutomaticallyAfterViolation) {
  ManualTime t;
  Scanner s = started(RestartMode::kStartInterlock, t);
  const auto id = s.edit_scene(t.now).add(intruder());
  s.advance(t.advance(milliseconds(120)));
  ASSERT_FALSE(s.ossd());
  ASSERT_TRUE(s.edit_scene(t.now).remove(id.value()));
  s.advance(t.advance(milliseconds(40)));
  EXPECT_TRUE(s.ossd());
}

// [RS4 manual §4.3]: the pulse must last 0.12 … 5 s.
TEST(ScannerTiming, RestartPulseWindow) {
  struct Pulse {
    std::chrono::microseconds length;
    bool accepted;
  };
  const Pulse pulses[] = {{milliseconds(119), false},
                          {milliseconds(120), true},
                          {milliseconds(5000), true},
                          {milliseconds(5001), false},
                          {std::chrono::microseconds(119999), false}};
  for (const Pulse& p : pulses) {
    ManualTime t;
    Scanner s = booted(params(RestartMode::kStartInterlock), t);
    s.set_restart_input(true, t.now);
    s.set_restart_input(false, t.advance(p.length));
    EXPECT_EQ(s.ossd(), p.accepted) << p.length.count() << " us";
    EXPECT_EQ(s.counters().restart_accepted, p.accepted ? 1U : 0U);
    EXPECT_EQ(s.counters().restart_too_short + s.counters().restart_too_long, p.accepted ? 0U : 1U);
  }
}

// [RS4 manual §4.3]: while the restart input is held the OSSDs are off, also in automatic mode.
TEST(ScannerTiming, HeldRestartKeepsOssdOff) {
  ManualTime t;
  Scanner s = booted(params(RestartMode::kAutomatic), t);
  ASSERT_TRUE(s.ossd());
  s.set_restart_input(true, t.now);
  EXPECT_FALSE(s.ossd());
  for (int i = 0; i < 10; ++i) {
    s.advance(t.advance(seconds(1)));
    EXPECT_FALSE(s.ossd());
  }
  s.set_restart_input(false, t.now);  // 10 s: refused, no effect needed
  EXPECT_TRUE(s.ossd());
  EXPECT_EQ(s.counters().restart_too_long, 1U);
}

TEST(ScannerTiming, ScanCounterCountsRevolutionsAndWraps) {
  ManualTime t;
  Scanner s = booted(params(RestartMode::kAutomatic), t);
  EXPECT_EQ(s.status().scan_counter, 1U);
  s.advance(t.advance(milliseconds(400)));
  EXPECT_EQ(s.status().scan_counter, 11U);
  EXPECT_EQ(s.last_scan().scan_number, 11U);
  // 2^32 − 11 more scans bring the 32-bit counter back to 0, one more to 1.
  const std::uint64_t to_wrap = (std::uint64_t{1} << 32) - 11U;
  s.advance(t.advance(milliseconds(40) * static_cast<std::int64_t>(to_wrap)));
  EXPECT_EQ(s.status().scan_counter, 0U);
  s.advance(t.advance(milliseconds(40)));
  EXPECT_EQ(s.status().scan_counter, 1U);
  EXPECT_EQ(s.counters().scans, (std::uint64_t{1} << 32) + 1U);
}

// Jumping far ahead gives the same state as stepping scan by scan.
TEST(ScannerTiming, FastForwardEqualsStepping) {
  ManualTime a;
  ManualTime b;
  Scanner jump = booted(params(RestartMode::kStartRestartInterlock), a);
  Scanner step = booted(params(RestartMode::kStartRestartInterlock), b);
  ASSERT_TRUE(jump.edit_scene(a.now).add(intruder()));
  ASSERT_TRUE(step.edit_scene(b.now).add(intruder()));
  jump.advance(a.advance(seconds(7)));
  for (int i = 0; i < 7000; ++i) step.advance(b.advance(milliseconds(1)));
  EXPECT_EQ(jump.status().scan_counter, step.status().scan_counter);
  EXPECT_EQ(jump.ossd(), step.ossd());
  EXPECT_EQ(jump.status().restart_interlock, step.status().restart_interlock);
  EXPECT_EQ(jump.last_scan().contour, step.last_scan().contour);
  EXPECT_EQ(jump.next_deadline(), step.next_deadline());
}

// The scanner's own LEDs: LED3 red exactly while the restart input is held ([RS4 manual §4.3]),
// whatever the pulse's length; LED5 yellow blinking from the contamination warning on
// ([RS4 manual §8.3]; 49 % no, 50 % yes); dark while powered off.
TEST(ScannerLeds, Led3WhileTheRestartIsHeldLed5OnAContaminatedWindow) {
  ManualTime t;
  Scanner s = booted(params(RestartMode::kStartRestartInterlock), t);
  EXPECT_EQ(s.leds(), ScannerLeds{});
  s.set_restart_input(true, t.now);
  EXPECT_TRUE(s.leds().led3_red);
  s.advance(t.advance(seconds(6)));  // held too long: still red while held
  EXPECT_TRUE(s.leds().led3_red);
  s.set_restart_input(false, t.now);
  EXPECT_FALSE(s.leds().led3_red);
  s.set_contamination(49, t.now);
  EXPECT_FALSE(s.leds().led5_yellow_blinking);
  s.set_contamination(50, t.now);
  EXPECT_TRUE(s.leds().led5_yellow_blinking);
  s.set_contamination(90, t.now);  // a fault: still the contaminated window
  EXPECT_TRUE(s.leds().led5_yellow_blinking);
  s.set_restart_input(true, t.now);
  s.power_off(t.now);
  EXPECT_EQ(s.leds(), ScannerLeds{}) << "dark without power";
}

}  // namespace
}  // namespace rs4sim::rs4::scanner
