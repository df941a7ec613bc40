// dp_link_cycles: runs exactly N bus cycles of bench_dp_link's 125-slave setup, for counting
// instructions with callgrind without Google Benchmark's probe runs. Instructions per cycle =
// (Ir of `dp_link_cycles 400` - Ir of `dp_link_cycles 100`) / 300: the setup drops out
// (docs/dp-link.md "Measured").
#include "bench/dp/link/bus_of_125.h"

#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv) {
  using namespace rs4sim;
  using bench::one_bus_cycle;
  const long cycles = argc > 1 ? std::strtol(argv[1], nullptr, 10) : 100;
  dp::devices::GenericBus b(bench::bus_of_125());
  if (!bench::reach_steady_state(b)) {
    std::fputs("slaves did not reach Data_Exch\n", stderr);
    return 1;
  }
  for (long i = 0; i < cycles; ++i) one_bus_cycle(b);
  std::printf("%ld cycles, %llu master cycles\n", cycles,
              static_cast<unsigned long long>(b.master().counters().cycles));
  return 0;
}
