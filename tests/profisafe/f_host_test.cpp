// F-host driver on injected time ([PROFIsafe V1.30 F-Device behaviour], [RS4 manual §7.3.2]
// passivation). Device PDUs are built with build_pdu, independent of FDevice.
#include "profisafe/f_host.h"

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

class ProfisafeFHostTest : public ::testing::Test {
 protected:
  ProfisafeFHostTest() : host_(config()) {}
  static FHostConfig config() {
    FHostConfig c;
    c.params.wd_time_ms = 100;
    return c;
  }
  Bytes device_pdu(std::uint8_t data, std::uint8_t status, std::uint8_t n) const {
    const PduConfig c = PduConfig::from(host_params(), 1);
    std::array<std::uint8_t, kMaxPduSize> out{};
    const auto size = build_pdu(c, Bytes{data}, status, n, out);
    return {out.begin(), out.begin() + static_cast<std::ptrdiff_t>(size.value())};
  }
  static FParameters host_params() {
    FParameters p = config().params;
    p.par_crc = crc1(p);
    return p;
  }
  PduCheck request(TimePoint t) {
    const auto r = host_.request(t);
    sent_.assign(r.begin(), r.end());  // PduCheck::data points into sent_
    return check_pdu(PduConfig::from(host_params(), 1), sent_);
  }
  // Bring the host to kRun: first answer healthy.
  void start(TimePoint t) {
    (void)request(t);
    ASSERT_EQ(host_.on_pdu(device_pdu(0x80, 0, 1), t), FHostEvent::kValid);
    ASSERT_EQ(host_.state(), FHostState::kRun);
  }

  FHost host_;
  Bytes sent_;
};

TEST_F(ProfisafeFHostTest, StartupPassivatedThenAutomaticReintegration) {
  host_.set_output(Bytes{0x42});
  EXPECT_TRUE(host_.passivated());
  const auto first = request(kT0);
  ASSERT_TRUE(first.ok());
  EXPECT_EQ(first.consecutive_number, 1);
  EXPECT_EQ(first.data[0], 0x00);                                // fail-safe output values
  EXPECT_EQ(first.status_or_control, control_bit::kActivateFv);  // while passivated
  EXPECT_EQ(host_.input()[0], 0);
  EXPECT_EQ(host_.on_pdu(device_pdu(0x80, status_bit::kFvActivated, 1), kT0 + 1ms),
            FHostEvent::kValid);
  EXPECT_EQ(host_.state(), FHostState::kRun);
  EXPECT_FALSE(host_.ack_req());
  const auto second = request(kT0 + 2ms);
  EXPECT_EQ(second.consecutive_number, 2);
  EXPECT_EQ(second.data[0], 0x42);
  EXPECT_EQ(second.status_or_control, 0x00);
  ASSERT_EQ(host_.on_pdu(device_pdu(0x80, 0, 2), kT0 + 3ms), FHostEvent::kValid);
  EXPECT_EQ(host_.input()[0], 0x80);
}

TEST_F(ProfisafeFHostTest, SameNumberUntilAnswered) {
  EXPECT_EQ(request(kT0).consecutive_number, 1);
  EXPECT_EQ(request(kT0 + 1ms).consecutive_number, 1);
  EXPECT_EQ(host_.counters().requests, 2u);
}

TEST_F(ProfisafeFHostTest, WatchdogExpiresAtFWdTimeNotBefore) {
  start(kT0);
  (void)request(kT0 + 10ms);  // number 2 sent: watchdog runs from here
  EXPECT_EQ(host_.next_deadline(), kT0 + 110ms);
  (void)request(kT0 + 60ms);  // resending does not restart it
  host_.on_time(kT0 + 110ms - 1ns);
  EXPECT_EQ(host_.state(), FHostState::kRun);
  host_.on_time(kT0 + 110ms);
  EXPECT_TRUE(host_.passivated());
  EXPECT_EQ(host_.counters().watchdog_timeouts, 1u);
  EXPECT_EQ(host_.input()[0], 0);
}

TEST_F(ProfisafeFHostTest, CrcErrorPassivatesAckReqAckRei) {
  start(kT0);
  (void)request(kT0 + 1ms);
  Bytes bad = device_pdu(0x80, 0, 2);
  bad[3] ^= 0x80;
  EXPECT_EQ(host_.on_pdu(bad, kT0 + 2ms), FHostEvent::kCrcError);
  EXPECT_EQ(host_.state(), FHostState::kPassivated);
  EXPECT_EQ(host_.counters().crc_errors, 1u);
  EXPECT_EQ(host_.counters().passivations, 1u);
  EXPECT_EQ(host_.input()[0], 0);
  host_.ack_rei();  // no effect before ACK_REQ
  EXPECT_EQ(host_.state(), FHostState::kPassivated);
  EXPECT_EQ(host_.on_pdu(device_pdu(0x80, 0, 2), kT0 + 3ms), FHostEvent::kValid);
  EXPECT_TRUE(host_.ack_req());
  EXPECT_EQ(host_.input()[0], 0);  // still the substitute value until ACK_REI
  host_.ack_rei();
  EXPECT_EQ(host_.state(), FHostState::kRun);
  EXPECT_EQ(host_.counters().reintegrations, 1u);
  (void)request(kT0 + 4ms);
  ASSERT_EQ(host_.on_pdu(device_pdu(0x81, 0, 3), kT0 + 5ms), FHostEvent::kValid);
  EXPECT_EQ(host_.input()[0], 0x81);
}

TEST_F(ProfisafeFHostTest, NumberErrorAndStaleAnswer) {
  start(kT0);
  (void)request(kT0 + 1ms);  // number 2
  EXPECT_EQ(host_.on_pdu(device_pdu(0x80, 0, 1), kT0 + 2ms), FHostEvent::kStale);
  EXPECT_EQ(host_.state(), FHostState::kRun);
  EXPECT_EQ(host_.on_pdu(device_pdu(0x80, 0, 7), kT0 + 3ms), FHostEvent::kNumberError);
  EXPECT_EQ(host_.counters().number_errors, 1u);
  EXPECT_TRUE(host_.passivated());
}

TEST_F(ProfisafeFHostTest, DeviceReportedFaultsPassivate) {
  start(kT0);
  (void)request(kT0 + 1ms);
  EXPECT_EQ(
      host_.on_pdu(device_pdu(0, status_bit::kWdTimeout | status_bit::kFvActivated, 2), kT0 + 2ms),
      FHostEvent::kDeviceFault);
  EXPECT_EQ(host_.counters().device_wd_timeout, 1u);
  EXPECT_TRUE(host_.passivated());
  (void)request(kT0 + 3ms);
  EXPECT_EQ(
      host_.on_pdu(device_pdu(0, status_bit::kCeCrc | status_bit::kFvActivated, 3), kT0 + 4ms),
      FHostEvent::kDeviceFault);
  EXPECT_EQ(host_.counters().device_ce_crc, 1u);
  EXPECT_FALSE(host_.ack_req());
}

TEST_F(ProfisafeFHostTest, InjectedPduFaults) {
  start(kT0);
  host_.faults().corrupt_crc2 = 1;
  EXPECT_EQ(request(kT0 + 1ms).error, ProfisafeError::kPduCrc2Mismatch);
  EXPECT_TRUE(request(kT0 + 2ms).ok());
  host_.faults().repeat_number = 1;
  EXPECT_EQ(request(kT0 + 3ms).consecutive_number, 1);  // the previous PDU again
  EXPECT_EQ(request(kT0 + 4ms).consecutive_number, 2);
  ASSERT_EQ(host_.on_pdu(device_pdu(0, 0, 2), kT0 + 5ms), FHostEvent::kValid);
  host_.faults().skip_number = 1;
  EXPECT_EQ(request(kT0 + 6ms).consecutive_number, 4);  // 3 skipped
  host_.faults().mute = true;
  EXPECT_TRUE(host_.request(kT0 + 7ms).empty());
  host_.faults().mute = false;
  host_.faults().crc1_override = 0xBEEF;
  ASSERT_EQ(host_.on_pdu(device_pdu(0, 0, 4), kT0 + 8ms), FHostEvent::kValid);
  EXPECT_EQ(request(kT0 + 9ms).error, ProfisafeError::kPduCrc2Mismatch);
}

TEST_F(ProfisafeFHostTest, InjectedParameterFaultsGiveTheDeviceDiagnosis) {
  const DeviceProfile profile{};  // F_Dest_Add 504, as the host is configured
  EXPECT_TRUE(validate(host_.parameter_block(), profile).ok());
  host_.parameter_faults().dest_add = 505;
  EXPECT_EQ(validate(host_.parameter_block(), profile).fault, FParameterFault::kDestAddMismatch);
  host_.parameter_faults() = {};
  host_.parameter_faults().source_add = 0;
  EXPECT_EQ(validate(host_.parameter_block(), profile).fault, FParameterFault::kSourceAddInvalid);
  host_.parameter_faults() = {};
  host_.parameter_faults().par_crc = 0x5430;  // the manual's unreproducible screenshot value
  const auto v = validate(host_.parameter_block(), profile);
  EXPECT_EQ(v.fault, FParameterFault::kCrc1Mismatch);
  EXPECT_EQ(v.received_crc1, 0x5430);
}

TEST(ProfisafeFHostConfig, RejectsParametersOfNoConnection) {
  FHostConfig c;
  c.params.par_version = 1;  // V2 with the 2-byte CRC2
  EXPECT_THROW(FHost{c}, std::invalid_argument);
  c = {};
  c.params.crc_length = CrcLength::k3Byte;
  EXPECT_THROW(FHost{c}, std::invalid_argument);
  c = {};
  c.data_size = 13;
  EXPECT_THROW(FHost{c}, std::invalid_argument);
}

// PlcView.fhost_state and the "fhost-state" event show these words; clients compare them.
TEST(ProfisafeFHostState, EveryStateHasItsApiWord) {
  EXPECT_EQ(to_token(FHostState::kStartup), "startup");
  EXPECT_EQ(to_token(FHostState::kRun), "run");
  EXPECT_EQ(to_token(FHostState::kPassivated), "passivated");
  EXPECT_EQ(to_token(FHostState::kAckRequired), "ack-required");
  EXPECT_EQ(to_token(static_cast<FHostState>(200)), "?");
  EXPECT_STREQ(to_string(FHostState::kAckRequired), "ack-required");  // logs print the same
}

}  // namespace
}  // namespace rs4sim::profisafe
