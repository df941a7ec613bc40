// Boot → data exchange → OSSD on with a free field ([RS4 manual §2.3, §2.4, §5.1, §7.1, §7.2]).
#include "rs4_fixture.h"

namespace rs4sim::rs4::device::testing {
namespace {

TEST(Rs4Startup, BootToOssdOnWithAFreeField) {
  Rs4Segment s(segment_config());
  const auto t0 = s.now();
  s.power_on();
  ASSERT_TRUE(s.run_until([&] { return s.in_data_exchange(); }, 5s));
  // Cyclic exchange runs independently of the RS4: held at OSSD 0, "not operational"
  // ([RS4 manual §5.1]).
  s.run_for(20s);
  EXPECT_EQ(s.input_byte() & kInputOssd, 0);
  EXPECT_NE(s.input_byte() & kInputOperatingState, 0);
  // ≈30 s after power-on the RS4 is operational and the Proxy-Request is set
  // ([RS4 manual §7.1, §7.2]).
  const auto up = time_until(
      s, [&] { return (s.input_byte() & kInputProxyRequest) != 0; }, 15s);
  ASSERT_TRUE(up.has_value());
  EXPECT_GE(s.now() - t0, kBoot);
  EXPECT_LE(s.now() - t0, kBoot + 500ms);
  // Factory setting: start/restart interlock → OSSD stays 0 until a restart pulse.
  s.run_for(1s);
  EXPECT_EQ(s.input_byte() & kInputOssd, 0);
  EXPECT_EQ(s.input_byte() & kInputOperatingState, 0);
  s.set_output_byte(kOutputRestart | 0x01);
  s.run_for(200ms);
  s.set_output_byte(0x01);
  EXPECT_TRUE(s.run_until([&] { return (s.input_byte() & kInputOssd) != 0; }, 500ms));
  EXPECT_TRUE(s.device().scanner().ossd());
  EXPECT_EQ(s.input_byte() & kInputProtectiveField, 0);
}

TEST(Rs4Startup, RestartPulseBeforeBootDoesNotReleaseOssd) {
  Rs4Segment s(segment_config());
  s.power_on();
  ASSERT_TRUE(s.run_until([&] { return s.in_data_exchange(); }, 5s));
  s.set_output_byte(kOutputRestart | 0x01);
  s.run_for(200ms);
  s.set_output_byte(0x01);
  s.run_for(10s);
  EXPECT_EQ(s.input_byte() & kInputOssd, 0);
}

}  // namespace
}  // namespace rs4sim::rs4::device::testing
