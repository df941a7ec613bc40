// The wake contract [stream/byte_device.h point 4], kept by the core alone: on a
// stream::MemoryLine, which like the ByteRunner's timer reads the deadline only after its own
// calls and on a wake, a change made from outside (the API, no poke) reaches the line on time.
#include "tests/gridscan/gridscan_line.h"

namespace rs4sim::gridscan::testing {
namespace {

TEST(GridScanWake, APowerCycleFromOutsideSendsThePowerUpMessageAtOnce) {
  Rig l(Options{});
  boot(l);
  l.device().power_off();
  const auto on = l.now();
  l.device().power_on(on);
  l.run_for(10ms);
  const auto got = l.take();
  ASSERT_EQ(got.size(), 1U);
  EXPECT_EQ(got[0].start, on);
  EXPECT_EQ(got[0].bytes[5], 0xA0);  // Info: Get version, answer
}

TEST(GridScanWake, ALateAnswerClearedFromOutsideLeavesAtTheCycleEnd) {
  Rig l(Options{});
  const auto ready = boot(l);
  Faults late;
  late.transmit.late = 20ms;
  l.device().set_faults(late);
  l.run_to(ready + 5ms);
  l.write(request(2, CommandId::kInfoCommunicationTest));
  l.run_to(ready + 15ms);  // cut by its idle gap: answered at ready + 30 ms + 20 ms
  l.device().set_faults(Faults{});  // cleared before the cycle end: at ready + 30 ms
  l.run_to(ready + 60ms);
  const auto got = l.take();
  ASSERT_EQ(got.size(), 1U);
  EXPECT_EQ(got[0].start, ready + 30ms);
}

TEST(GridScanWake, AFaultInjectedFromOutsideDelaysThePendingAnswer) {
  Rig l(Options{});
  const auto ready = boot(l);
  l.run_to(ready + 5ms);
  l.write(request(2, CommandId::kInfoCommunicationTest));
  l.run_to(ready + 15ms);
  Faults late;
  late.transmit.late = 20ms;
  l.device().set_faults(late);
  l.run_to(ready + 49ms);
  EXPECT_TRUE(l.quiet());
  l.run_to(ready + 51ms);
  const auto got = l.take();
  ASSERT_EQ(got.size(), 1U);
  EXPECT_EQ(got[0].start, ready + 50ms);
}

}  // namespace
}  // namespace rs4sim::gridscan::testing
