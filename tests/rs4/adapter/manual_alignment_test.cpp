// Behaviours where the manual is read one way among several, each pinned by a test and
// explained in docs/decisions.md: the error bit, alarms of persisting warnings, the 0x53 of a
// rejected command, PROFI_CMD_RESET and the RS4's inputs, inconsistent outputs (0x2419),
// acyclic services while the PC adapter is attached, and the LED's blink patterns.
#include "adapter_rig.h"
#include "rs4/adapter/rs4_commands.h"

namespace rs4sim::rs4::adapter::testing {
namespace {

using Bytes = std::vector<std::uint8_t>;

struct Aligned : ::testing::Test {
  Rig rig;
  void SetUp() override {
    rig.start();
    rig.run(31s);
    rig.restart_pulse();
    ASSERT_TRUE(rig.ossd());
    rig.control.alarms.clear();
  }
};

// [docs/decisions.md#rs4-error-bit]: a one-shot adapter error (here 0x2A0B, a block number out of
// sequence) sets input bit 5 until its going alarm; the RS4 keeps protecting (OSSD 1).
TEST_F(Aligned, AdapterErrorSetsTheErrorBitUntilTheGoingAlarm) {
  rig.write({0x00, 0x05, 0x00, 0x01, 0x90});  // block 1 without block 0: 0x2A0B
  rig.run(40ms);
  EXPECT_EQ(rig.adapter.error_memory().last_error().uc2_error, 0x2A0B);
  EXPECT_TRUE(rig.host_input() & kInputError);
  EXPECT_TRUE(rig.ossd());
  rig.run(400ms);
  EXPECT_TRUE(rig.host_input() & kInputError) << "< 500 ms without error";
  rig.run(200ms);
  EXPECT_EQ(rig.alarms_of(1, 2), 1u) << "going";
  EXPECT_FALSE(rig.host_input() & kInputError);
}

// [RS4 manual §5.3.2]: the going alarm follows ≥500 ms *without* the error; a contamination
// warning that persists stays "coming".
TEST_F(Aligned, PersistingWarningGetsNoGoingAlarm) {
  rig.adapter.scanner().set_contamination(60, rig.now);  // warning level: 0x54
  rig.run(100ms);
  ASSERT_EQ(rig.alarms_of(1, 1), 1u);
  rig.run(2s);
  EXPECT_EQ(rig.alarms_of(1, 2), 0u) << "still contaminated";
  EXPECT_FALSE(rig.host_input() & kInputError) << "a warning is not an error";
  rig.adapter.scanner().set_contamination(0, rig.now);
  rig.run(700ms);
  EXPECT_EQ(rig.alarms_of(1, 2), 1u);
}

// [docs/decisions.md#rs4-rejected-command]: the RS4 answers an unknown command with 0x53
// (error 0x0501, parameter = the command byte); the adapter enters it like any RS4 error
// (μC2 ring, diagnosis alarm); the RS4 keeps protecting.
TEST_F(Aligned, UnknownCommandIsAnRs4ErrorWithAlarm) {
  rig.write(Rig::block({0x7E}));
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
  EXPECT_TRUE(rig.ossd());
  EXPECT_EQ(rig.adapter.scanner().status().state, scanner::ScannerState::kMeasuring);
}

// [RS4 manual §5.2.2]: PROFI_CMD_RESET does not affect the RS4: the field pair it monitors stays
// until the PROFIBUS start-up after the reset selects pair 1 ([RS4 manual §5.1.2]).
TEST_F(Aligned, AdapterResetLeavesTheRs4sFieldPair) {
  rig.out_byte = 0x03;
  rig.run(100ms);
  ASSERT_EQ(rig.adapter.scanner().status().first_pair, 3);
  rig.write(Rig::block({0x94}));
  EXPECT_EQ(rig.adapter.scanner().status().first_pair, 3) << "the reset itself";
  rig.advance(100ms);
  EXPECT_EQ(rig.adapter.scanner().status().first_pair, 3) << "link down";
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
  rig.out_byte = 0x02;
  rig.run(100ms);
  EXPECT_EQ(rig.adapter.scanner().status().first_pair, 2);
  EXPECT_FALSE(rig.host_input() & kInputError);
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

// [RS4 manual §4.4]: fast blink ≈5 Hz; the fault blink is slower (1 Hz, a DECISION); steady
// states are lit, "connected" and "dark" are not.
TEST(LedPatterns, BlinkRates) {
  using namespace std::chrono_literals;
  EXPECT_EQ(led_pattern(LedState::kFastBlink), (LedPattern{100ms, 200ms}));
  EXPECT_EQ(led_pattern(LedState::kSlowBlink), (LedPattern{500ms, 1000ms}));
  EXPECT_TRUE(led_lit(LedState::kFastBlink, 0ms));
  EXPECT_FALSE(led_lit(LedState::kFastBlink, 150ms));
  EXPECT_TRUE(led_lit(LedState::kFastBlink, 1250ms));
  EXPECT_FALSE(led_lit(LedState::kSlowBlink, 700ms));
  EXPECT_TRUE(led_lit(LedState::kSteadyInit, 5s));
  EXPECT_TRUE(led_lit(LedState::kSteadyFault, 5s));
  EXPECT_FALSE(led_lit(LedState::kOffConnected, 0ms));
  EXPECT_FALSE(led_lit(LedState::kDark, 0ms));
}

}  // namespace
}  // namespace rs4sim::rs4::adapter::testing
