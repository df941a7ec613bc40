// F-host and F-device together, one DP data exchange per cycle on injected time: the
// scenarios of [RS4 manual §7.3.2] (passivation → ACK_REQ → ACK_REI) provoked through the
// fault-injection API of both sides, for each connection the drivers serve: V1 (2-byte CRC2, the
// RS4) and V2 with the 3- and the 4-byte CRC2 ([IEC 61784-3-3 safety PDU]).
#include "profisafe/f_device.h"
#include "profisafe/f_host.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

namespace rs4sim::profisafe {
namespace {

using namespace std::chrono_literals;

struct Connection {
  const char* name;
  std::uint8_t par_version;
  CrcLength crc_length;
  std::size_t pdu_size;  // 1 data byte + status/control + [V1 number] + CRC2
};

class ProfisafeLoop : public ::testing::TestWithParam<Connection> {
 protected:
  ProfisafeLoop() : host_(host_config()), dev_(FDeviceConfig{device_profile(), 1, {}}) {
    EXPECT_TRUE(dev_.set_parameters(host_.parameter_block()).ok());
    const std::uint8_t in = 0x80;  // OSSD on
    dev_.set_input(std::span<const std::uint8_t>(&in, 1));
    const std::uint8_t out = 0x41;  // Proxy-Enable, field pair 1
    host_.set_output(std::span<const std::uint8_t>(&out, 1));
  }
  static FHostConfig host_config() {
    FHostConfig c;
    c.params.wd_time_ms = 100;
    c.params.par_version = GetParam().par_version;
    c.params.crc_length = GetParam().crc_length;
    return c;
  }
  static DeviceProfile device_profile() {
    DeviceProfile p;
    p.par_version = GetParam().par_version;
    p.crc_length = GetParam().crc_length;
    return p;
  }
  // One bus cycle of 10 ms; a muted side sends nothing and the peer sees nothing.
  void cycle() {
    now_ += 10ms;
    dev_.on_time(now_);
    const auto req = host_.request(now_);
    if (!req.empty()) (void)dev_.on_pdu(req, now_);
    const auto resp = dev_.response();
    if (!req.empty() && !resp.empty()) (void)host_.on_pdu(resp, now_);
  }
  void cycles(int n) {
    for (int i = 0; i < n; ++i) cycle();
  }
  std::uint8_t host_input() const { return host_.input()[0]; }

  FHost host_;
  FDevice dev_;
  TimePoint now_{std::chrono::hours(1)};
};

TEST_P(ProfisafeLoop, StartupReachesProcessValuesBothWays) {
  EXPECT_EQ(host_.request(now_).size(), GetParam().pdu_size);
  cycle();  // host passivated: fail-safe outputs with activate_FV; device answers FV
  EXPECT_EQ(host_input(), 0);
  EXPECT_EQ(host_.state(), FHostState::kRun);  // first healthy answer reintegrates at start-up
  cycles(2);
  EXPECT_EQ(host_input(), 0x80);
  EXPECT_EQ(dev_.output()[0], 0x41);
  EXPECT_TRUE(dev_.sends_process_values());
  EXPECT_EQ(host_.counters().passivations, 0u);
}

TEST_P(ProfisafeLoop, CorruptedHostPduPassivatesUntilAckRei) {
  cycles(3);
  host_.faults().corrupt_crc2 = 1;
  cycle();
  EXPECT_EQ(dev_.counters().crc_errors, 1u);
  EXPECT_EQ(dev_.output()[0], 0);  // device outputs fail-safe at once
  cycle();                         // device reports CE_CRC once
  EXPECT_EQ(host_.counters().device_ce_crc, 1u);
  EXPECT_TRUE(host_.passivated());
  EXPECT_EQ(host_input(), 0);
  cycles(3);  // healthy again
  EXPECT_TRUE(host_.ack_req());
  EXPECT_EQ(host_input(), 0);  // substitute value until ACK_REI
  host_.ack_rei();
  cycles(2);
  EXPECT_EQ(host_.state(), FHostState::kRun);
  EXPECT_EQ(host_input(), 0x80);
  EXPECT_EQ(dev_.output()[0], 0x41);
}

TEST_P(ProfisafeLoop, CorruptedDevicePduPassivates) {
  cycles(3);
  dev_.faults().corrupt_crc2 = 1;
  cycle();
  EXPECT_EQ(host_.counters().crc_errors, 1u);
  EXPECT_TRUE(host_.passivated());
  cycles(2);
  EXPECT_TRUE(host_.ack_req());
  host_.ack_rei();
  cycles(2);
  EXPECT_EQ(host_input(), 0x80);
}

TEST_P(ProfisafeLoop, MutedHostLetsBothWatchdogsExpire) {
  cycles(3);
  host_.faults().mute = true;
  cycles(9);  // 90 ms: not yet
  EXPECT_EQ(dev_.state(), FDeviceState::kRun);
  cycles(2);  // past F_WD_Time = 100 ms
  EXPECT_EQ(dev_.counters().watchdog_timeouts, 1u);
  EXPECT_EQ(host_.counters().watchdog_timeouts, 1u);
  EXPECT_FALSE(dev_.sends_process_values());
  host_.faults().mute = false;
  cycles(4);
  EXPECT_EQ(host_.counters().device_wd_timeout, 1u);  // the device reported WD_timeout once
  EXPECT_TRUE(host_.ack_req());
  host_.ack_rei();
  cycles(2);
  EXPECT_EQ(host_input(), 0x80);
  EXPECT_TRUE(dev_.sends_process_values());
}

TEST_P(ProfisafeLoop, SkippedHostNumberIsAFault) {
  cycles(3);
  host_.faults().skip_number = 1;
  cycle();
  EXPECT_EQ(dev_.counters().number_errors, 1u);
  cycles(2);
  EXPECT_TRUE(host_.passivated());
  cycles(2);
  EXPECT_TRUE(host_.ack_req());
}

TEST_P(ProfisafeLoop, RepeatedDevicePdusStarveTheHostWatchdog) {
  cycles(3);
  dev_.faults().repeat_number = 12;  // the device keeps sending its previous PDU: stale
  cycles(12);
  EXPECT_GE(host_.counters().stale, 10u);
  EXPECT_EQ(host_.counters().watchdog_timeouts, 1u);
  EXPECT_TRUE(host_.passivated());
}

TEST_P(ProfisafeLoop, WrongCrc1OnOneSideNeverGetsThrough) {
  host_.faults().crc1_override = 0x5430;
  cycles(20);
  EXPECT_GT(dev_.counters().crc_errors, 10u);
  EXPECT_EQ(dev_.counters().new_pdus, 0u);
  EXPECT_FALSE(dev_.sends_process_values());
  EXPECT_EQ(host_input(), 0);
  host_.faults().crc1_override.reset();
  cycles(3);  // the device syncs to the host's number even after faults at start-up
  EXPECT_TRUE(dev_.sends_process_values() || dev_.state() == FDeviceState::kFault);
  cycles(2);
  EXPECT_TRUE(dev_.sends_process_values());
}

INSTANTIATE_TEST_SUITE_P(Connections, ProfisafeLoop,
                         ::testing::Values(Connection{"V1", 0, CrcLength::k2Byte, 5},
                                           Connection{"V2_3byte", 1, CrcLength::k3Byte, 5},
                                           Connection{"V2_4byte", 1, CrcLength::k4Byte, 6}),
                         [](const auto& tpi) { return std::string(tpi.param.name); });

}  // namespace
}  // namespace rs4sim::profisafe

namespace rs4sim::profisafe {
namespace {

TEST(ProfisafeLoopWide, FourDataBytesEachWay) {
  FHostConfig hc;
  hc.data_size = 4;
  hc.params.check_seqnr = true;
  FHost host(hc);
  FDevice dev(FDeviceConfig{DeviceProfile{}, 4, {}});
  ASSERT_TRUE(dev.set_parameters(host.parameter_block()).ok());
  const std::array<std::uint8_t, 4> in{0xDE, 0xAD, 0xBE, 0xEF}, out{1, 2, 3, 4};
  dev.set_input(in);
  host.set_output(out);
  TimePoint now{std::chrono::hours(1)};
  for (int i = 0; i < 3; ++i) {
    now += std::chrono::milliseconds(5);
    const auto req = host.request(now);
    EXPECT_EQ(req.size(), 8u);  // 4 data + control + number + 2 CRC2
    (void)dev.on_pdu(req, now);
    EXPECT_NE(host.on_pdu(dev.response(), now), FHostEvent::kCrcError);
  }
  EXPECT_TRUE(std::equal(in.begin(), in.end(), host.input().begin()));
  EXPECT_TRUE(std::equal(out.begin(), out.end(), dev.output().begin()));
}

}  // namespace
}  // namespace rs4sim::profisafe
