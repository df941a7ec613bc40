// Fault injection for each of the controller's SIL 2 checks ([GridScan manual §10.2]) and
// the LEDs of an internal failure ([GridScan manual §13]).
#include "device_harness.h"

namespace rs4sim::gridscan::testing {
namespace {

const Bytes kClearState{0x43, 0x45, 0x44, 0x45, 0x03, 0xB0, 0x16, 0x00, 0xB0, 0x50, 0x3D, 0x98};

std::vector<Sent> reduced_state(DeviceHarness& h) {
  return h.exchange(request(2, CommandId::kDataReducedState));
}

TEST(GridScanFaults, NoneGivesTheKnownFrame) {
  DeviceHarness h;
  h.boot();
  const auto s = reduced_state(h);
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(s[0].bytes, kClearState);
}

TEST(GridScanFaults, LateAnswer) {
  DeviceHarness h;
  h.boot();
  const auto ready = h.clock.now();
  h.device.set_faults({.transmit = {.late = 50ms}});
  const auto s = reduced_state(h);
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(s[0].bytes, kClearState);
  EXPECT_EQ(s[0].at, ready + 80ms);  // cycle end + 50 ms
}

TEST(GridScanFaults, WrongSeqCntDirectionBitBadCrc) {
  DeviceHarness h;
  h.boot();
  h.device.set_faults({.wrong_seq = true});
  auto s = reduced_state(h);
  EXPECT_EQ(decode_response(s.at(0).bytes, 22).value().seq, 4);
  h.device.set_faults({.direction_bit = true});
  s = h.exchange(request(4, CommandId::kDataReducedState));  // the device counted right
  EXPECT_EQ(decode_response(s.at(0).bytes, 22).error(), FrameError::kDirectionBit);
  h.device.set_faults({.bad_crc = true});
  s = h.exchange(request(6, CommandId::kDataReducedState));
  EXPECT_EQ(decode_response(s.at(0).bytes, 22).error(), FrameError::kBadCrc);
  h.device.set_faults({.transmit = {.silent = true}});
  EXPECT_TRUE(h.exchange(request(8, CommandId::kDataReducedState)).empty());
  h.device.set_faults({});
  s = h.exchange(request(10, CommandId::kDataReducedState));
  EXPECT_EQ(decode_response(s.at(0).bytes, 22).value().seq, 11);
}

TEST(GridScanFaults, InternalFailure) {
  DeviceHarness h;
  h.boot();
  h.device.set_internal_failure(true);
  const auto s = reduced_state(h);
  EXPECT_EQ(decode_response(s.at(0).bytes, 22).value().payload[1], 0x02);  // bit 9
  EXPECT_EQ(h.device.leds(h.clock.now()).rx_red, Led::kBlinkFast);
}

TEST(GridScanFaults, ConfigNotSet) {
  DeviceHarness h;
  h.boot();
  h.device.set_faults({.config_not_set = true});
  h.exchange(request(2, CommandId::kModeSetStandBy));
  h.exchange(request(4, CommandId::kConfigAllowChange));
  h.exchange(request(6, CommandId::kConfigGetCurrent));
  const auto s = h.exchange(request(8, CommandId::kConfigSetStatic));
  EXPECT_EQ(decode_response(s.at(0).bytes, 22).value(), (Frame{9, 0xD1, {1}}));
}

TEST(GridScanFaults, PowerOffSilencesTheDevice) {
  DeviceHarness h;
  h.boot();
  h.device.power_off();
  EXPECT_TRUE(reduced_state(h).empty());
  EXPECT_EQ(h.device.leds(h.clock.now()), Leds{});
  EXPECT_EQ(h.device.next_deadline(), std::nullopt);
}

}  // namespace
}  // namespace rs4sim::gridscan::testing
