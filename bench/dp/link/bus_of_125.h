#pragma once
// The 125-slave bus both bench_dp_link and dp_link_cycles measure: our master and 125 generic
// slaves (2 bytes in and out each) in Data_Exch, cycling back to back.
#include "dp/devices/generic_bus.h"

namespace rs4sim::bench {

using namespace std::chrono_literals;

inline dp::devices::GenericBusConfig bus_of_125() {
  dp::devices::GenericBusConfig c;
  c.master_address = 0;
  c.cycle_target = 1us;  // cycles back to back
  for (std::uint8_t a = 1; a <= 125; ++a)
    c.slaves.push_back({a, 0x1234, {0x31}, true});  // 2 B in/out
  return c;
}

// All 125 slaves in Data_Exch, then 50 ms more for the steady state; false when they did not
// get there within 5 s.
inline bool reach_steady_state(dp::devices::GenericBus& b) {
  if (!b.run_until([&] { return b.slaves_in_data_exchange() == 125; }, 5s)) return false;
  b.run_for(50ms);
  return true;
}

// One poll cycle; out of line so that callgrind can count it alone
// (valgrind --tool=callgrind --toggle-collect='*one_bus_cycle*'; divide by the calls it
// reports only for a run of >= 100 of them: each fresh bus starts with a part-cycle).
[[gnu::noinline]] inline void one_bus_cycle(dp::devices::GenericBus& b) {
  const auto target = b.master().counters().cycles + 1;
  b.run_until([&] { return b.master().counters().cycles >= target; }, 1s);
}

}  // namespace rs4sim::bench
