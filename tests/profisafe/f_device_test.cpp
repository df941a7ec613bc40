// F-device driver on injected time ([PROFIsafe V1.30 F-Device behaviour], docs/profisafe.md
// "recovery rules"). Host PDUs are built with build_pdu from the RS4 defaults, independent of
// FHost.
#include "profisafe/f_device.h"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <vector>

namespace rs4sim::profisafe {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;

const TimePoint kT0{std::chrono::hours(1)};

class ProfisafeFDeviceTest : public ::testing::Test {
 protected:
  ProfisafeFDeviceTest() : dev_(FDeviceConfig{DeviceProfile{}, 1, {}}) {}

  void parameterise(std::uint16_t wd_ms = 10) {
    FParameters p;
    p.wd_time_ms = wd_ms;
    const auto block = encode_f_parameters(p);
    ASSERT_TRUE(dev_.set_parameters(block).ok());
    host_ = PduConfig::from(parse_f_parameters(block).value(), 1);
  }
  Bytes host_pdu(std::uint8_t data, std::uint8_t control, std::uint8_t n) const {
    std::array<std::uint8_t, kMaxPduSize> out{};
    const auto size = build_pdu(host_, Bytes{data}, control, n, out);
    return {out.begin(), out.begin() + static_cast<std::ptrdiff_t>(size.value())};
  }
  Bytes response() {
    const auto r = dev_.response();
    return {r.begin(), r.end()};
  }
  // Valid device PDU (as the host checks it) with the given fields.
  void expect_response(std::uint8_t data, std::uint8_t status, std::uint8_t n) {
    const Bytes r = response();
    const auto c = check_pdu(host_, r);
    ASSERT_TRUE(c.ok()) << c.received_crc2 << " " << c.computed_crc2;
    EXPECT_EQ(c.data[0], data);
    EXPECT_EQ(c.status_or_control, status);
    EXPECT_EQ(c.consecutive_number, n);
  }

  FDevice dev_;
  PduConfig host_{};
};

TEST_F(ProfisafeFDeviceTest, BeforeParametersAllZeroPduAndIgnored) {
  EXPECT_EQ(response(), Bytes(5, 0));
  EXPECT_EQ(dev_.state(), FDeviceState::kNoParameters);
  EXPECT_EQ(dev_.on_pdu(Bytes{1, 2, 3, 4, 5}, kT0), FDeviceEvent::kIgnored);
  EXPECT_FALSE(dev_.sends_process_values());
  EXPECT_EQ(dev_.next_deadline(), std::nullopt);
}

TEST_F(ProfisafeFDeviceTest, WrongParametersKeepDiagnosis) {
  FParameters p;
  p.dest_add = 505;
  const auto v = dev_.set_parameters(encode_f_parameters(p));
  EXPECT_EQ(v.fault, FParameterFault::kDestAddMismatch);
  // The status PDU the RS4 reports for it: tests/rs4/safety/diagnosis_test.cpp.
  EXPECT_EQ(dev_.last_validation().fault, FParameterFault::kDestAddMismatch);
  EXPECT_EQ(dev_.state(), FDeviceState::kNoParameters);
  EXPECT_EQ(dev_.counters().parameter_errors, 1u);
}

TEST_F(ProfisafeFDeviceTest, StartupSendsFailSafeUntilFirstValidPdu) {
  parameterise();
  dev_.set_input(Bytes{0x80});
  EXPECT_EQ(dev_.state(), FDeviceState::kStartup);
  // data 0 (fail-safe), status FV_activated, number 0, CRC2 (candidate rule, number not covered)
  EXPECT_EQ(response(), (Bytes{0x00, 0x10, 0x00, 0x5B, 0xE3}));
  EXPECT_EQ(dev_.next_deadline(), std::nullopt);  // the watchdog starts with the first PDU
  EXPECT_EQ(dev_.on_pdu(host_pdu(0x05, 0x00, 1), kT0), FDeviceEvent::kNew);
  EXPECT_EQ(dev_.state(), FDeviceState::kRun);
  EXPECT_TRUE(dev_.sends_process_values());
  EXPECT_EQ(dev_.output()[0], 0x05);
  // Candidate-rule CRC2 of data 0x80, status 0, number 1 (bitwise reference): 73 0B.
  EXPECT_EQ(response(), (Bytes{0x80, 0x00, 0x01, 0x73, 0x0B}));
}

TEST_F(ProfisafeFDeviceTest, WatchdogExpiresAtFWdTimeNotBefore) {
  parameterise(50);
  ASSERT_EQ(dev_.on_pdu(host_pdu(0, 0, 1), kT0), FDeviceEvent::kNew);
  EXPECT_EQ(dev_.next_deadline(), kT0 + 50ms);
  dev_.on_time(kT0 + 50ms - 1ns);
  EXPECT_EQ(dev_.state(), FDeviceState::kRun);
  // A repeat does not restart the watchdog.
  EXPECT_EQ(dev_.on_pdu(host_pdu(0, 0, 1), kT0 + 40ms), FDeviceEvent::kRepeat);
  EXPECT_EQ(dev_.next_deadline(), kT0 + 50ms);
  dev_.on_time(kT0 + 50ms);
  EXPECT_EQ(dev_.state(), FDeviceState::kFault);
  EXPECT_EQ(dev_.counters().watchdog_timeouts, 1u);
  EXPECT_FALSE(dev_.sends_process_values());
  EXPECT_EQ(dev_.status_byte(), status_bit::kWdTimeout | status_bit::kFvActivated);
  EXPECT_EQ(dev_.output()[0], 0);
}

TEST_F(ProfisafeFDeviceTest, NewPduRestartsWatchdog) {
  parameterise(50);
  ASSERT_EQ(dev_.on_pdu(host_pdu(0, 0, 1), kT0), FDeviceEvent::kNew);
  ASSERT_EQ(dev_.on_pdu(host_pdu(0, 0, 2), kT0 + 49ms), FDeviceEvent::kNew);
  EXPECT_EQ(dev_.next_deadline(), kT0 + 99ms);
  dev_.on_time(kT0 + 98ms);
  EXPECT_EQ(dev_.state(), FDeviceState::kRun);
  // A PDU arriving exactly at the deadline is too late.
  EXPECT_EQ(dev_.on_pdu(host_pdu(0, 0, 3), kT0 + 99ms), FDeviceEvent::kNew);
  EXPECT_EQ(dev_.counters().watchdog_timeouts, 1u);
  EXPECT_EQ(dev_.state(), FDeviceState::kFault);
}

TEST_F(ProfisafeFDeviceTest, CrcErrorFailSafeAndRecovery) {
  parameterise();
  dev_.set_input(Bytes{0x80});
  ASSERT_EQ(dev_.on_pdu(host_pdu(0x01, 0, 1), kT0), FDeviceEvent::kNew);
  Bytes bad = host_pdu(0x02, 0, 2);
  bad[4] ^= 0x01;
  EXPECT_EQ(dev_.on_pdu(bad, kT0 + 1ms), FDeviceEvent::kCrcError);
  EXPECT_EQ(dev_.counters().crc_errors, 1u);
  EXPECT_EQ(dev_.output()[0], 0);
  expect_response(0x00, status_bit::kCeCrc | status_bit::kFvActivated, 1);  // last valid number
  // Rule: the first valid new PDU after the fault is answered with the fault status...
  EXPECT_EQ(dev_.on_pdu(host_pdu(0x02, 0, 2), kT0 + 2ms), FDeviceEvent::kNew);
  expect_response(0x00, status_bit::kCeCrc | status_bit::kFvActivated, 2);
  EXPECT_EQ(dev_.output()[0], 0);
  // ...the next one returns to process values.
  EXPECT_EQ(dev_.on_pdu(host_pdu(0x03, 0, 3), kT0 + 3ms), FDeviceEvent::kNew);
  expect_response(0x80, 0x00, 3);
  EXPECT_EQ(dev_.output()[0], 0x03);
}

TEST_F(ProfisafeFDeviceTest, WrongSizeIsCrcError) {
  parameterise();
  EXPECT_EQ(dev_.on_pdu(Bytes{0, 0, 1, 0}, kT0), FDeviceEvent::kCrcError);
  EXPECT_EQ(dev_.last_check().error, ProfisafeError::kPduWrongSize);
}

TEST_F(ProfisafeFDeviceTest, ConsecutiveNumberErrorIsCommunicationFault) {
  parameterise();
  ASSERT_EQ(dev_.on_pdu(host_pdu(0, 0, 1), kT0), FDeviceEvent::kNew);
  EXPECT_EQ(dev_.on_pdu(host_pdu(0, 0, 3), kT0 + 1ms), FDeviceEvent::kNumberError);
  EXPECT_EQ(dev_.counters().number_errors, 1u);
  EXPECT_EQ(dev_.state(), FDeviceState::kFault);
  EXPECT_EQ(dev_.status_byte(), status_bit::kCeCrc | status_bit::kFvActivated);
}

TEST_F(ProfisafeFDeviceTest, NumbersWrap255To1) {
  parameterise();
  ASSERT_EQ(dev_.on_pdu(host_pdu(0, 0, 255), kT0), FDeviceEvent::kNew);
  EXPECT_EQ(dev_.on_pdu(host_pdu(0, 0, 1), kT0 + 1ms), FDeviceEvent::kNew);
  EXPECT_EQ(dev_.on_pdu(host_pdu(0, 0, 0), kT0 + 2ms), FDeviceEvent::kNumberError);
}

TEST_F(ProfisafeFDeviceTest, ActivateFvHonouredAndReported) {
  parameterise();
  dev_.set_input(Bytes{0x80});
  ASSERT_EQ(dev_.on_pdu(host_pdu(0x07, control_bit::kActivateFv, 1), kT0), FDeviceEvent::kNew);
  EXPECT_FALSE(dev_.sends_process_values());
  EXPECT_EQ(dev_.output()[0], 0);
  expect_response(0x00, status_bit::kFvActivated, 1);
  ASSERT_EQ(dev_.on_pdu(host_pdu(0x07, 0x00, 2), kT0 + 1ms), FDeviceEvent::kNew);
  EXPECT_TRUE(dev_.sends_process_values());
  EXPECT_EQ(dev_.output()[0], 0x07);
  expect_response(0x80, 0x00, 2);
}

TEST_F(ProfisafeFDeviceTest, ThePredicateAloneDecidesTheInputByte) {
  parameterise();
  dev_.set_input(Bytes{0xFF});
  const Bytes steps[] = {host_pdu(0, 0, 1), host_pdu(0, control_bit::kActivateFv, 2),
                         host_pdu(0, 0, 3), host_pdu(0, 0, 9),
                         host_pdu(0, 0, 4), host_pdu(0, 0, 5)};
  TimePoint t = kT0;
  for (const Bytes& s : steps) {
    (void)dev_.on_pdu(s, t);
    t += 1ms;
    const Bytes r = response();
    const auto c = check_pdu(host_, r);
    ASSERT_TRUE(c.ok());
    EXPECT_EQ(c.data[0] == 0xFF, dev_.sends_process_values());
    EXPECT_EQ((c.status_or_control & status_bit::kFvActivated) == 0, dev_.sends_process_values());
  }
}

TEST_F(ProfisafeFDeviceTest, InjectedFaultsOnResponses) {
  parameterise();
  dev_.set_input(Bytes{0x80});
  ASSERT_EQ(dev_.on_pdu(host_pdu(0, 0, 1), kT0), FDeviceEvent::kNew);
  const Bytes good = response();
  dev_.faults().corrupt_crc2 = 1;
  EXPECT_EQ(check_pdu(host_, response()).error, ProfisafeError::kPduCrc2Mismatch);
  EXPECT_EQ(response(), good);  // counted down
  dev_.faults().mute = true;
  EXPECT_TRUE(dev_.response().empty());
  dev_.faults().mute = false;
  dev_.faults().skip_number = 1;
  EXPECT_EQ(check_pdu(host_, response()).consecutive_number, 2);
  EXPECT_EQ(check_pdu(host_, response()).consecutive_number, 1);  // one PDU only
  ASSERT_EQ(dev_.on_pdu(host_pdu(0, 0, 2), kT0 + 1ms), FDeviceEvent::kNew);
  dev_.faults().repeat_number = 1;
  EXPECT_EQ(check_pdu(host_, response()).consecutive_number, 1);  // the previously sent PDU again
  EXPECT_EQ(check_pdu(host_, response()).consecutive_number, 2);
  dev_.faults().crc1_override = 0x1234;
  EXPECT_EQ(check_pdu(host_, response()).error, ProfisafeError::kPduCrc2Mismatch);
}

}  // namespace
}  // namespace rs4sim::profisafe

namespace rs4sim::profisafe {
namespace {

TEST(ProfisafeFDeviceConfig, RejectsProfilesOfNoConnection) {
  FDeviceConfig c{DeviceProfile{}, 1, {}};
  c.profile.par_version = 1;  // V2 with the 2-byte CRC2
  EXPECT_THROW(FDevice{c}, std::invalid_argument);
  c.profile = DeviceProfile{};
  c.profile.crc_length = CrcLength::k3Byte;  // V1 with the 3-byte CRC2
  EXPECT_THROW(FDevice{c}, std::invalid_argument);
  c.profile = DeviceProfile{};
  c.data_size = 0;
  EXPECT_THROW(FDevice{c}, std::invalid_argument);
  c.data_size = 12;
  EXPECT_NO_THROW(FDevice{c});
}

// DeviceState.fdevice_state and the "fdevice-state" event show these words.
TEST(ProfisafeFDeviceState, EveryStateHasItsApiWord) {
  EXPECT_EQ(to_token(FDeviceState::kNoParameters), "no-parameters");
  EXPECT_EQ(to_token(FDeviceState::kStartup), "startup");
  EXPECT_EQ(to_token(FDeviceState::kRun), "run");
  EXPECT_EQ(to_token(FDeviceState::kFault), "fault");
  EXPECT_EQ(to_token(static_cast<FDeviceState>(200)), "?");
  EXPECT_STREQ(to_string(FDeviceState::kNoParameters), "no-parameters");  // logs print the same
}

}  // namespace
}  // namespace rs4sim::profisafe
