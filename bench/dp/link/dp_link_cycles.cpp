// dp_link_cycles: runs exactly N bus cycles of bench_dp_link's 125-slave setup, for counting
// instructions with callgrind without Google Benchmark's probe runs. Instructions per cycle =
// (Ir of `dp_link_cycles 400` - Ir of `dp_link_cycles 100`) / 300: the setup drops out
// (docs/dp-link.md "Measured").
#include "dp/devices/generic_bus.h"

#include <cstdio>
#include <cstdlib>

namespace {

using namespace rs4sim;
using namespace std::chrono_literals;

dp::devices::GenericBusConfig bus_of_125() {
  dp::devices::GenericBusConfig c;
  c.master_address = 0;
  c.cycle_target = 1us;  // cycles back to back
  for (std::uint8_t a = 1; a <= 125; ++a)
    c.slaves.push_back({a, 0x1234, {0x31}, true});  // 2 B in/out
  return c;
}

[[gnu::noinline]] void one_bus_cycle(dp::devices::GenericBus& b) {
  const auto target = b.master().counters().cycles + 1;
  b.run_until([&] { return b.master().counters().cycles >= target; }, 1s);
}

}  // namespace

int main(int argc, char** argv) {
  const long cycles = argc > 1 ? std::strtol(argv[1], nullptr, 10) : 100;
  dp::devices::GenericBus b(bus_of_125());
  if (!b.run_until([&] { return b.slaves_in_data_exchange() == 125; }, 5s)) {
    std::fputs("slaves did not reach Data_Exch\n", stderr);
    return 1;
  }
  b.run_for(50ms);  // steady state, as in bench_dp_link
  for (long i = 0; i < cycles; ++i) one_bus_cycle(b);
  std::printf("%ld cycles, %llu master cycles\n", cycles,
              static_cast<unsigned long long>(b.master().counters().cycles));
  return 0;
}
