// Behaviours where the manual is read one way among several, each pinned by a test and
// explained in docs/decisions.md: the error bit, alarms of lasting warnings, the 0x53 of a
// rejected command, PROFI_CMD_RESET and the RS4's inputs, inconsistent outputs (0x2419),
// acyclic services while the PC adapter is attached, and the LED's blink patterns.
#include "adapter_rig.h"
#include "rs4/adapter/rs4_commands.h"

namespace rs4sim::rs4::adapter::testing {
namespace {

struct Aligned : ::testing::Test {
  Rig rig;
  void SetUp() override {
    ASSERT_TRUE(rig.boot_and_release());
    rig.control.alarms.clear();
  }
  // The error bit of a one-shot adapter error raised at `at`, with OSSD 0, until its going
  // alarm 500 ms after the error (the `going`-th), and the F-host sees the OSSD bit again:
  // both sides of the bound [RS4 manual §5.1.1, §5.3.2].
  void expect_error_bit_until_going_alarm(dp::TimePoint at, std::size_t going,
                                          const char* going_note) {
    rig.advance(499ms);
    EXPECT_EQ(rig.adapter.input_byte() & (kInputError | kInputOssd), kInputError) << "499 ms";
    EXPECT_EQ(rig.alarms_of(1, 2), going - 1);
    rig.advance(1ms);
    EXPECT_EQ(rig.now - at, 500ms);
    EXPECT_EQ(rig.alarms_of(1, 2), going) << going_note;
    EXPECT_EQ(rig.adapter.input_byte() & (kInputError | kInputOssd), kInputOssd) << "500 ms";
    rig.run(40ms);
  }
};

// [RS4 manual §5.1.1] bit 5 "(OSSD = 0 im Fehlerfall)" [docs/decisions.md#rs4-error-bit]: a
// one-shot adapter error (here 0x2A0B, a block number out of sequence) sets bit 5 and clears
// bit 7 until its going alarm, 500 ms after the error: both sides of the bound.
TEST_F(Aligned, AdapterErrorSetsTheErrorBitAndOssd0UntilTheGoingAlarm) {
  const auto at = rig.now;
  rig.write({0x00, 0x05, 0x00, 0x01, 0x90});  // block 1 without block 0: 0x2A0B
  EXPECT_EQ(rig.adapter.error_memory().last_error().uc2_error, 0x2A0B);
  rig.advance(0ms);
  EXPECT_EQ(rig.adapter.input_byte() & (kInputError | kInputOssd), kInputError) << "at once";
  EXPECT_TRUE(rig.adapter.scanner().ossd()) << "the RS4 itself keeps protecting";
  expect_error_bit_until_going_alarm(at, 1, "going at 500 ms");
  EXPECT_TRUE(rig.ossd()) << "the F-host sees the OSSD bit again";
}

// The invariant of [RS4 manual §5.1.1] bit 5 for every source of the error bit: sampled every
// millisecond, no input byte has bit 5 and bit 7 both set, and each source does set bit 5.
TEST_F(Aligned, ErrorBitNeverShowsWithOssd1) {
  const auto watch = [&](const char* what, auto provoke, auto clear) {
    bool seen_error = false;
    provoke();
    for (int ms = 0; ms < 1500; ++ms) {
      rig.advance(1ms);
      if (ms % 20 == 0) rig.cycle();
      const auto b = rig.adapter.input_byte();
      seen_error |= (b & kInputError) != 0;
      ASSERT_NE(b & (kInputError | kInputOssd), kInputError | kInputOssd) << what << " " << ms;
    }
    EXPECT_TRUE(seen_error) << what;
    clear();
    rig.run(1s);
    rig.restart_pulse();
    rig.restart_pulse();
    ASSERT_TRUE(rig.ossd()) << "after " << what;
  };
  watch("RS4 fault", [&] {
    ASSERT_TRUE(rig.adapter.scanner().inject_fault(scanner::Fault::kDazzled, rig.now));
  }, [&] { ASSERT_TRUE(rig.adapter.scanner().clear_fault(scanner::Fault::kDazzled, rig.now)); });
  watch("wrong field pair 0x2600", [&] { rig.out_byte = 0x05; }, [&] { rig.out_byte = 0x01; });
  watch("inconsistent outputs 0x2419", [&] { rig.out_byte = 0x09; }, [&] { rig.out_byte = 0x01; });
  watch("one-shot 0x2A0B", [&] { rig.write({0x00, 0x05, 0x00, 0x01, 0x90}); }, [] {});
}

// [RS4 manual §5.1.1] bit 5 "Es ist ein Fehler im RS4 oder im PROFIsafe-Adapter aufgetreten": a
// proxy error of table 5.3-3 (0x2B09, reported with a failed PROFI_CMD_PROXY_END) is an error of
// the adapter: bit 5 from the report until its going alarm, 500 ms later [docs/decisions.md#rs4-error-bit].
TEST_F(Aligned, ProxyErrorSetsTheErrorBitUntilItsGoingAlarm) {
  rig.write(Rig::block({0x98}));
  ASSERT_EQ(rig.read_answer().at(0), 0x98);
  ASSERT_EQ(rig.adapter.proxy_phase(), ProxyPhase::kSyncRunning);
  const auto at = rig.now;
  rig.write(Rig::block({0x99, 0x01, 0x2B, 0x09}));  // failed: error in the CRC comparison
  EXPECT_EQ(rig.read_answer(), (Bytes{0x99, 0x01, 0x01}));
  EXPECT_EQ(rig.adapter.error_memory().last_error().uc1_error, 0x2B09);
  EXPECT_EQ(rig.alarms_of(1, 1), 1u);
  rig.advance(499ms);
  EXPECT_EQ(rig.adapter.input_byte() & (kInputError | kInputOssd), kInputError) << "499 ms";
  rig.advance(1ms);
  EXPECT_EQ(rig.now - at, 500ms);
  EXPECT_EQ(rig.alarms_of(1, 2), 1u) << "going at 500 ms";
  EXPECT_FALSE(rig.adapter.input_byte() & kInputError) << "500 ms";
}

// DECISION [docs/decisions.md#rs4-error-bit]: an RS4 command the RS4 refuses (here 0x10 with a
// wrong password, 0x53 0503) is entered in the error memory with a diagnosis alarm
// ([RS4 manual §5.3.2]) but is no error state of the RS4 or the adapter: bit 5 stays 0 and the
// OSSD bit 1, sampled every millisecond until the going alarm.
TEST_F(Aligned, RefusedCommandRaisesAnAlarmButNeverBit5) {
  rig.write(Rig::block({0x10, 0x21, 'W', 'R', 'O', 'N', 'G', 0xFF, 0xFF, 0xFF}));
  const auto answer = rig.read_answer();
  ASSERT_FALSE(answer.empty());
  EXPECT_EQ(answer[0], 0x53);
  EXPECT_EQ(rig.adapter.error_memory().last_error().uc2_error, kRs4ErrorWrongPassword);
  EXPECT_EQ(rig.alarms_of(1, 1), 1u);
  for (int ms = 0; ms < 600; ++ms) {
    rig.advance(1ms);
    ASSERT_EQ(rig.adapter.input_byte() & (kInputError | kInputOssd), kInputOssd) << ms;
  }
  EXPECT_EQ(rig.alarms_of(1, 2), 1u);
}

// [RS4 manual §5.3.2] "Fehler oder Warnungen des RS4 … werden … als Diagnose-Alarme gemeldet" and
// "Liegt mindestens 500 ms kein Fehler mehr vor, so wird ein gehender Alarm gesendet": a
// contamination warning is reported coming; being no error (input bit 5 stays 0), it does not
// hold the going alarm back, which follows 500 ms later while the window is still dirty
// [docs/decisions.md#rs4-going-alarm-and-warnings].
TEST_F(Aligned, WarningIsReportedButHoldsNoGoingAlarmBack) {
  const auto at = rig.now;
  rig.adapter.scanner().set_contamination(60, rig.now);  // warning level: 0x54 at once
  rig.advance(1ms);
  EXPECT_EQ(rig.alarms_of(1, 1), 1u) << "coming";
  rig.advance(498ms);
  EXPECT_EQ(rig.now - at, 499ms);
  EXPECT_EQ(rig.alarms_of(1, 2), 0u) << "499 ms";
  rig.advance(1ms);
  EXPECT_EQ(rig.alarms_of(1, 2), 1u) << "going at 500 ms";
  EXPECT_TRUE(rig.adapter.scanner().status().contamination_warning) << "still dirty";
  rig.run(2s);
  EXPECT_EQ(rig.alarms_of(1, 1), 1u) << "reported once";
  EXPECT_FALSE(rig.host_input() & kInputError) << "a warning is not an error";
  EXPECT_FALSE(rig.host_input() & kInputWarningOutputN) << "warning output active (inverted)";
  EXPECT_TRUE(rig.ossd());
}

// [RS4 manual §5.3.2] "Liegt mindestens 500 ms kein Fehler mehr vor, so wird ein gehender Alarm
// gesendet": a one-shot adapter error (0x2A0B) while the window is dirty goes 500 ms after the
// error, and with it bit 5; the OSSD bit follows the RS4 again although the warning lasts.
// Before the fix the warning held the going alarm, bit 5 and OSSD 0 until the window was clean.
TEST_F(Aligned, OneShotErrorWithADirtyWindowGoesAfter500ms) {
  rig.adapter.scanner().set_contamination(60, rig.now);
  rig.run(1s);  // the warning came and went
  ASSERT_EQ(rig.alarms_of(1, 2), 1u);
  ASSERT_TRUE(rig.adapter.scanner().status().contamination_warning);
  const auto at = rig.now;
  rig.write({0x00, 0x05, 0x00, 0x01, 0x90});  // block 1 without block 0: 0x2A0B
  ASSERT_EQ(rig.adapter.error_memory().last_error().uc2_error, 0x2A0B);
  expect_error_bit_until_going_alarm(at, 2, "going at 500 ms despite the warning");
  EXPECT_TRUE(rig.ossd());
  EXPECT_TRUE(rig.adapter.scanner().status().contamination_warning);
}

// [RS4 manual §5.2.2] "Bei jedem empfangenen Klasse 1- oder Klasse 2-Telegramm wird anhand des
// ersten Bytes ermittelt, ob es für den PROFIsafe-Adapter bestimmt ist oder für den RS4": a class 2
// master's 0x90 and 0x84 are the adapter's, answered as the manual's tables give them, and never
// reach the RS4 (which would take them for unknown commands and leave protection). The commands
// that steer the adapter are refused 93 01 code [docs/decisions.md#rs4-class2-adapter-commands].
TEST_F(Aligned, Class2AdapterCommandsAreTheAdaptersNotTheRs4s) {
  using dp::slave::AcyclicChannel;
  rig.write(Rig::block({0x90}), 2, AcyclicChannel::kC2, true);
  const auto version = rig.read_answer(240, AcyclicChannel::kC2);
  ASSERT_EQ(version.size(), 10u);  // table 5.2-6: 90, PROFIsafe 1.0, DP 1.0, 0x11 0x0D, 3 bytes
  EXPECT_EQ(Bytes(version.begin(), version.begin() + 7),
            (Bytes{0x90, 0x01, 0x00, 0x01, 0x00, 0x11, 0x0D}));
  rig.write(Rig::block({0x84}), 2, AcyclicChannel::kC2);
  const auto last = rig.read_answer(240, AcyclicChannel::kC2);
  ASSERT_EQ(last.size(), 9u);  // table 5.2-7: 84, μC2 error, count, μC1 error, count
  EXPECT_EQ(last[0], 0x84);
  rig.write(Rig::block({0x94}), 2, AcyclicChannel::kC2);  // PROFI_CMD_RESET: steers the adapter
  EXPECT_EQ(rig.read_answer(240, AcyclicChannel::kC2), (Bytes{0x93, 0x01, 0x94}));
  EXPECT_EQ(rig.adapter.counters().resets, 0u);
  EXPECT_FALSE(rig.adapter.wants_link_down_until());
  rig.write(Rig::block({0x92, 0x01, 0x01}), 2, AcyclicChannel::kC2);  // forwarding: C1's
  EXPECT_EQ(rig.read_answer(240, AcyclicChannel::kC2), (Bytes{0x93, 0x01, 0x92}));
  rig.write(Rig::block({0x90, 0x00}), 2, AcyclicChannel::kC2);  // table 5.2-3: wrong length
  EXPECT_EQ(rig.read_answer(240, AcyclicChannel::kC2), (Bytes{0x93, 0x00, 0x90}));
  EXPECT_EQ(rig.adapter.counters().rs4_commands, 0u) << "nothing reached the RS4";
  EXPECT_EQ(rig.adapter.scanner().status().state, scanner::ScannerState::kMeasuring);
  EXPECT_EQ(rig.adapter.error_memory().last_error().uc2_error, 0);
  rig.run(100ms);
  EXPECT_TRUE(rig.ossd()) << "the machine keeps running";
  EXPECT_EQ(rig.alarms_of(1, 1), 0u) << "no diagnosis alarm";
}

// [RS4 manual §5.2.2]: a telegram the RS4 does not know is answered with 0x53 (error 0x0501,
// parameter = the command byte) "(RS4 geht in Fehlerzustand)": OSSD off, the error in the μC2
// ring and a diagnosis alarm, once; a restart pulse acknowledges it (no lasting cause)
// [docs/decisions.md#rs4-rejected-command].
TEST_F(Aligned, UnknownCommandPutsTheRs4IntoItsErrorState) {
  ASSERT_TRUE(rig.ossd());
  rig.write(Rig::block({0x7E, 0x01}));  // an unknown code, option 1 = one option byte
  const auto answer = rig.read_answer();
  ASSERT_FALSE(answer.empty());
  EXPECT_EQ(answer[0], 0x53);
  const auto last = rig.adapter.error_memory().last_error();
  EXPECT_EQ(last.uc2_error, kRs4ErrorUnknownCommand);
  EXPECT_EQ(last.uc1_error, 0);
  rig.run(40ms);
  ASSERT_EQ(rig.alarms_of(1, 1), 1u);
  EXPECT_EQ(rig.control.alarms[0].user_data, (Bytes{0x84, 0x05, 0x01, 0x00, 0x01,  // μC2 0x0501 ×1
                                                    0x00, 0x00, 0x00, 0x00}));     // μC1 none
  EXPECT_FALSE(rig.ossd());
  EXPECT_EQ(rig.adapter.scanner().status().state, scanner::ScannerState::kError);
  EXPECT_TRUE(rig.host_input() & kInputError);  // bit 5, with OSSD 0 [RS4 manual §5.1.1]
  rig.run(1s);
  EXPECT_FALSE(rig.ossd()) << "latched until acknowledged";
  rig.restart_pulse();  // acknowledges the error: a new start, measuring again
  EXPECT_EQ(rig.adapter.scanner().status().state, scanner::ScannerState::kMeasuring);
  EXPECT_FALSE(rig.ossd()) << "the start interlock of the new start";
  rig.restart_pulse();  // releases the start interlock [RS4 manual §4.3]
  EXPECT_TRUE(rig.ossd());
}


// [RS4 manual §5.2.2]: PROFI_CMD_RESET does not affect the RS4: the field pair it monitors stays
// until the PROFIBUS start-up after the reset selects pair 1 ([RS4 manual §5.1.2]). The test
// first proves the reset took place (link down for 2 s, adapter initialising, counted), and ends
// with the start-up that does change the pair.
TEST_F(Aligned, AdapterResetLeavesTheRs4sFieldPair) {
  rig.out_byte = 0x03;
  rig.run(100ms);
  ASSERT_EQ(rig.adapter.scanner().status().first_pair, 3);
  ASSERT_EQ(rig.adapter.counters().resets, 0u);
  rig.write(Rig::block({0x94}));
  ASSERT_EQ(rig.adapter.counters().resets, 1u) << "the reset was executed";
  ASSERT_EQ(rig.adapter.wants_link_down_until(), rig.now + 2s) << "ca. 2 s link down";
  EXPECT_EQ(rig.adapter.led(), LedState::kSteadyInit) << "the adapter restarts";
  EXPECT_FALSE(rig.adapter.view().connected);
  EXPECT_EQ(rig.adapter.scanner().status().first_pair, 3) << "the reset itself";
  rig.advance(100ms);
  EXPECT_EQ(rig.adapter.scanner().status().first_pair, 3) << "link down";
  rig.start(/*power=*/false);  // the master's new start-up after the reset
  EXPECT_EQ(rig.adapter.scanner().status().first_pair, 1) << "the start-up selects pair 1";
}

// [docs/decisions.md#rs4-inconsistent-outputs]: reserved output bits 5..3 set → 0x2419 once,
// the byte is not applied (pair kept, restart low), error bit set while it lasts.
TEST_F(Aligned, ReservedOutputBitsGive2419AndTheByteIsNotApplied) {
  rig.out_byte = 0x0A;  // bit 3 set, field pair 2
  rig.run(200ms);
  EXPECT_EQ(rig.adapter.error_memory().last_error().uc2_error, 0x2419);
  EXPECT_EQ(rig.adapter.error_memory().last_error().uc2_count, 1) << "reported once";
  EXPECT_EQ(rig.adapter.scanner().status().first_pair, 1);
  EXPECT_TRUE(rig.host_input() & kInputError);
  EXPECT_FALSE(rig.ossd()) << "[RS4 manual §5.1.1] bit 5: OSSD = 0 while the error lasts";
  EXPECT_TRUE(rig.adapter.scanner().ossd()) << "the RS4 itself keeps protecting";
  rig.out_byte = 0x02;
  rig.run(100ms);
  EXPECT_EQ(rig.adapter.scanner().status().first_pair, 2);
  EXPECT_FALSE(rig.host_input() & kInputError);
  EXPECT_TRUE(rig.ossd()) << "the OSSD bit follows the RS4 again";
}

TEST(AlignedConfig, ReservedBitCheckCanBeSwitchedOff) {
  AdapterConfig c;
  c.check_reserved_output_bits = false;
  Rig rig(c);
  rig.start();
  rig.run(31s);
  rig.out_byte = 0x0A;
  rig.run(200ms);
  EXPECT_EQ(rig.adapter.scanner().status().first_pair, 2);
  EXPECT_NE(rig.adapter.error_memory().last_error().uc2_error, 0x2419);
}

// [docs/decisions.md#rs4-pc-adapter-acyclic]: while the PC adapter is attached, WRITEs on either
// channel are accepted and ignored without an error ([RS4 manual §5.2.1]) and every READ answers
// the bare header with flow state 010: that state is the "error" of [RS4 manual §5.1.1, §7.1.2].
TEST_F(Aligned, BothChannelsSeeState010WhileThePcAdapterIsAttached) {
  rig.adapter.attach_pc_adapter(rig.now);
  for (const auto ch : {dp::slave::AcyclicChannel::kC1, dp::slave::AcyclicChannel::kC2}) {
    EXPECT_EQ(rig.write(Rig::block({0x90}), 2, ch).kind, dp::slave::AcyclicResult::Kind::kData);
    const auto r = rig.read(240, ch);
    EXPECT_EQ(Bytes(r.data.begin(), r.data.end()), (Bytes{0x20, 0x04, 0xFF, 0xFF}));  // 0 010 000 0: state 010, not ready
  }
  EXPECT_EQ(rig.adapter.error_memory().last_error().uc2_error, 0);
}

// [RS4 manual §4.4] "Ein schnelles Blinken (ca. 5 Hz)": ready for PROFIBUS once the 2.5 s of
// steady light are over; the adapter's LED, as `Adapter::led_lit` shows it (and the API's
// DeviceState.led_lit), is lit 100 ms of every 200 ms from the moment the blink began — both
// edges of each phase.
// The LED blinks from now on, lit `half` then dark `half`: both edges of each phase of the
// first period and the start of the next. Returns the blink's start.
dp::TimePoint expect_blink_from_now(Rig& rig, std::chrono::milliseconds half) {
  const auto start = rig.now;
  const auto lit = [&](std::chrono::milliseconds at) { return rig.adapter.led_lit(start + at); };
  EXPECT_TRUE(lit(0ms));
  EXPECT_TRUE(lit(half - 1ms));
  EXPECT_FALSE(lit(half));
  EXPECT_FALSE(lit(2 * half - 1ms));
  EXPECT_TRUE(lit(2 * half));
  return start;
}

TEST(LedPatterns, FastBlinkFollowsItsPatternFromItsStart) {
  Rig rig;
  rig.adapter.power_on(rig.now);
  EXPECT_TRUE(rig.adapter.led_lit(rig.now));
  rig.advance(2499ms);
  EXPECT_EQ(rig.adapter.led(), LedState::kSteadyInit);
  EXPECT_TRUE(rig.adapter.led_lit(rig.now)) << "steady";
  rig.advance(1ms);
  ASSERT_EQ(rig.adapter.led(), LedState::kFastBlink);
  const auto start = expect_blink_from_now(rig, 100ms);
  EXPECT_TRUE(rig.adapter.led_lit(start + 1299ms));
  EXPECT_FALSE(rig.adapter.led_lit(start + 1300ms));
  // Connected: off, whatever the phase.
  rig.advance(150ms);
  ASSERT_EQ(rig.adapter.check_parameters(set_prm_for(rig.params), rig.now),
            dp::slave::PrmVerdict::kAccept);
  ASSERT_EQ(rig.adapter.check_config(kRealConfig, false, rig.now), dp::slave::CfgVerdict::kAccept);
  rig.adapter.on_state_change(dp::slave::State::kWaitCfg, dp::slave::State::kDataExch,
                              dp::slave::TransitionReason::kCfgAccepted, rig.now);
  EXPECT_EQ(rig.adapter.led(), LedState::kOffConnected);
  EXPECT_FALSE(rig.adapter.led_lit(rig.now));
  EXPECT_FALSE(rig.adapter.led_lit(rig.now + 50ms));
}

// The fault blink, "einen Blinktakt kleiner ca. 5Hz" [RS4 manual §4.4], is 500 ms on, 500 ms off
// [docs/decisions.md#rs4-led-blink], starting lit when the F-parameters are refused (here a
// wrong F_Dest_Add), not in the phase of an earlier blink.
TEST(LedPatterns, SlowBlinkStartsLitWhenTheParametersAreRefused) {
  Rig rig(AdapterConfig{}, rs4_fparams(505));
  rig.adapter.power_on(rig.now);
  rig.advance(2500ms + 130ms);  // fast blink, 130 ms in: dark in its own phase
  ASSERT_EQ(rig.adapter.led(), LedState::kFastBlink);
  ASSERT_FALSE(rig.adapter.led_lit(rig.now));
  ASSERT_EQ(rig.adapter.check_parameters(set_prm_for(rig.params), rig.now),
            dp::slave::PrmVerdict::kPrmFault);
  ASSERT_EQ(rig.adapter.led(), LedState::kSlowBlink);
  expect_blink_from_now(rig, 500ms);
}

// Steps the adapter from deadline to deadline until `done` holds; returns false after 10 s.
template <class Pred>
bool step_until(Rig& rig, Pred done) {
  const auto limit = rig.now + 10s;
  while (!done()) {
    const auto next = rig.adapter.next_deadline();
    if (!next || *next > limit) return false;
    rig.now = std::max(rig.now, *next);
    rig.adapter.on_time(rig.now);
  }
  return true;
}

// "Reaktionszeit PROFIsafe-Adapter 10 ms" [RS4 manual, technical data]: what the RS4 shows reaches
// the input byte 10 ms later, not 9: first the protective field bit (the RS4 sees the
// obstacle), then the OSSD bit (the RS4 switches off after its own response time).
TEST_F(Aligned, AdapterAddsItsTenMillisecondResponseTime) {
  // Steps to the moment `rs4_shows` holds, then checks `bit` keeps its old value `before` for
  // 9 ms and takes the new one at 10 ms.
  const auto follows_10ms_later = [&](auto rs4_shows, std::uint8_t bit, bool before) {
    ASSERT_TRUE(step_until(rig, rs4_shows));
    const auto rs4_at = rig.now;
    EXPECT_EQ((rig.adapter.input_byte() & bit) != 0, before) << "the RS4 just changed";
    rig.advance(9ms);
    EXPECT_EQ((rig.adapter.input_byte() & bit) != 0, before) << "9 ms after the RS4";
    rig.advance(1ms);
    EXPECT_EQ((rig.adapter.input_byte() & bit) != 0, !before) << "10 ms after the RS4";
    EXPECT_EQ(rig.now - rs4_at, 10ms);
  };
  (void)rig.adapter.scanner().edit_scene(rig.now).add(scanner::Circle{{500, 0}, 100});
  rig.adapter.on_time(rig.now);
  follows_10ms_later([&] { return rig.adapter.scanner().status().protective_violated; },
                     kInputProtectiveField, false);
  follows_10ms_later([&] { return !rig.adapter.scanner().ossd(); }, kInputOssd, true);
}

// Starts the rig and runs it past the RS4's boot.
void boot(Rig& rig) {
  rig.start();
  rig.run(31s);
}

TEST(AdapterTiming, ResponseTimeZeroFollowsTheRs4AtOnce) {
  AdapterConfig cfg;
  cfg.response_time = 0ms;
  Rig rig(cfg);
  boot(rig);
  rig.restart_pulse();
  ASSERT_TRUE(rig.ossd());
  (void)rig.adapter.scanner().edit_scene(rig.now).add(scanner::Circle{{500, 0}, 100});
  rig.adapter.on_time(rig.now);
  ASSERT_TRUE(step_until(rig, [&] { return !rig.adapter.scanner().ossd(); }));
  EXPECT_FALSE(rig.adapter.input_byte() & kInputOssd);
}

// [RS4 manual §5.2.1] "Da der RS4 bis zu 2 Minuten braucht um Daten zu verarbeiten": the answer
// to an RS4 command is there after the processing time (default one scan, 40 ms); a READ
// before it carries the header only (flow byte: no payload), so the master polls.
TEST_F(Aligned, Rs4CommandAnswerComesAfterItsProcessingTime) {
  rig.write(Rig::block({0x14, 0x01}));  // COM_CMD_ALIVE
  auto r = rig.read();
  EXPECT_EQ(r.data.size(), 4u) << "header only";
  EXPECT_EQ(r.data[0] & 0x02, 0) << "flow byte bit 1: no payload";
  EXPECT_EQ(rig.adapter.pending_answers(dp::slave::AcyclicChannel::kC1), 1u);
  rig.advance(39ms);
  EXPECT_EQ(rig.read().data.size(), 4u) << "39 ms: still processing";
  rig.advance(1ms);
  r = rig.read();
  ASSERT_GT(r.data.size(), 4u) << "40 ms: answered";
  EXPECT_EQ(r.data[4], 0x14);
}

// Two commands in a row are processed one after the other: the second answer 80 ms after both.
TEST_F(Aligned, Rs4CommandsAreProcessedInOrder) {
  rig.write(Rig::block({0x14, 0x01}));
  rig.write(Rig::block({0x7E, 0x01}));  // unknown: 0x53
  rig.advance(40ms);
  auto first = rig.read();
  ASSERT_GT(first.data.size(), 4u);
  EXPECT_EQ(first.data[4], 0x14);
  EXPECT_EQ(rig.read().data.size(), 4u) << "40 ms: the second still processing";
  rig.advance(40ms);
  const auto second = rig.read();
  ASSERT_GT(second.data.size(), 4u);
  EXPECT_EQ(second.data[4], 0x53);
}

TEST(AdapterTiming, CommandTimeZeroAnswersAtOnce) {
  AdapterConfig cfg;
  cfg.rs4_command_time = 0ms;
  Rig rig(cfg);
  boot(rig);
  rig.write(Rig::block({0x14, 0x01}));
  const auto r = rig.read();
  ASSERT_GT(r.data.size(), 4u);
  EXPECT_EQ(r.data[4], 0x14);
}

}  // namespace
}  // namespace rs4sim::rs4::adapter::testing
