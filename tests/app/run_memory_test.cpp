// The memory of a simulated run (`rs4sim run --link memory`) does not grow with simulated
// time: the RS4 entry of the device registry, built and driven as the run does it (slices of
// one simulated second), holds the same heap after its second simulated hour as after its
// first. Before the run stopped keeping its segment's master events, every hour added about
// 130 MB (the heap of three master events per 10 ms cycle).
#include "app/devices/device_registry.h"

#include <gtest/gtest.h>
#include <malloc.h>

#include <chrono>

namespace rs4sim::app {
namespace {

// The heap in use, mmap()ed blocks included: a growing vector of events lives in one of those
// (uordblks alone does not count them).
std::size_t heap_in_use() {
  const auto m = mallinfo2();
  return m.uordblks + m.hblkhd;
}

void run_one_hour(SimulatedSegment& run) {
  for (int s = 0; s < 3600; ++s) run.run_for(std::chrono::seconds(1));
}

TEST(RunMemory, TheSecondSimulatedHourAddsNoHeap) {
  DeviceOptions options;
  const auto* rs4 = find_device("rs4");
  ASSERT_NE(rs4, nullptr);
  rs4->validate(options);
  auto run = rs4->simulate(options);
  run_one_hour(*run);
  ASSERT_TRUE(run->healthy());  // in data exchange: the bus carried its cycles
  const auto after_one = heap_in_use();
  run_one_hour(*run);
  const auto after_two = heap_in_use();
  // The bound: 1 MB, where keeping the events added about 130 MB an hour.
  EXPECT_LT(after_two, after_one + (1U << 20))
      << "the heap grew by " << (after_two - after_one) << " bytes in the second hour";
}

}  // namespace
}  // namespace rs4sim::app
