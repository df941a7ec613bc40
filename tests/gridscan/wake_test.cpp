// The wake contract [stream/byte_device.h point 4], kept by the core alone: on a
// stream::MemoryLine, which like the ByteRunner's timer reads the deadline only after its own
// calls and on a wake, a change made from outside (the API, no poke) reaches the line on time.
#include "device_harness.h"
#include "stream/memory_line.h"

namespace rs4sim::gridscan::testing {
namespace {

struct Line {
  stream::ManualClock clock;
  Device device{Options{}};
  stream::MemoryLine line{clock, device};
  stream::TimePoint t0 = clock.now();
  Line() {
    line.start();
    line.run_for(1702ms);  // both power-up messages are in (B0: 1700 ms + 12 characters)
    (void)line.take_received();
  }
};

TEST(GridScanWake, APowerCycleFromOutsideSendsThePowerUpMessageAtOnce) {
  Line l;
  l.device.power_off();
  const auto on = l.clock.now();
  l.device.power_on(on);
  l.line.run_for(10ms);
  const auto got = l.line.take_received();
  ASSERT_EQ(got.size(), 1U);
  EXPECT_EQ(got[0].start, on);
  EXPECT_EQ(got[0].bytes[5], 0xA0);  // Info: Get version, answer
}

TEST(GridScanWake, ALateAnswerClearedFromOutsideLeavesAtTheCycleEnd) {
  Line l;
  const auto ready = l.t0 + 1700ms;
  Faults late;
  late.transmit.late = 20ms;
  l.device.set_faults(late);
  l.line.run_until(ready + 5ms);
  l.line.write(request(2, CommandId::kInfoCommunicationTest));
  l.line.run_until(ready + 15ms);  // cut by its idle gap: answered at ready + 30 ms + 20 ms
  l.device.set_faults(Faults{});  // cleared before the cycle end: at ready + 30 ms
  l.line.run_until(ready + 60ms);
  const auto got = l.line.take_received();
  ASSERT_EQ(got.size(), 1U);
  EXPECT_EQ(got[0].start, ready + 30ms);
}

TEST(GridScanWake, AFaultInjectedFromOutsideDelaysThePendingAnswer) {
  Line l;
  const auto ready = l.t0 + 1700ms;
  l.line.run_until(ready + 5ms);
  l.line.write(request(2, CommandId::kInfoCommunicationTest));
  l.line.run_until(ready + 15ms);
  Faults late;
  late.transmit.late = 20ms;
  l.device.set_faults(late);
  l.line.run_until(ready + 49ms);
  EXPECT_TRUE(l.line.take_received().empty());
  l.line.run_until(ready + 51ms);
  const auto got = l.line.take_received();
  ASSERT_EQ(got.size(), 1U);
  EXPECT_EQ(got[0].start, ready + 50ms);
}

}  // namespace
}  // namespace rs4sim::gridscan::testing
