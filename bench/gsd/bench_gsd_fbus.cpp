// 125 GSD F-devices with our master as their F-host on the in-memory bus (docs/profisafe.md
// "Our master as F-host for GSD F-devices"): simulated seconds per wall second of the whole bus
// (our master, its F-hosts, the stations with their F-devices), against the same bus without
// PROFIsafe in the same run. The stations alternate between the project's V1 F-module file
// (8 bytes each way) and its V2 preset F-module file (12 bytes each way) at 12 Mbit/s; without
// PROFIsafe the same stations run with the same Set_Prm and Chk_Cfg and the same telegram
// lengths, only with no F-parameter block taken as one (no F-host, no F-device).
#include "app/runtime/master_service.h"
#include "dp/link/memory_bus.h"
#include "tests/test_paths.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <ostream>
#include <streambuf>

namespace {

using namespace std::chrono_literals;
namespace app = rs4sim::app;

std::string corpus(const char* file) {
  return rs4sim::testing::from_test_dir(RS4SIM_GSD_CORPUS_REL) + "/" + file;
}

// A stream that keeps nothing: the report's lines cost their formatting only.
class NullBuffer final : public std::streambuf {
 protected:
  int overflow(int c) override { return c; }
};

struct FBus125 {
  explicit FBus125(bool profisafe) {
    const auto v1 = app::load_gsd_station(corpus("f_module_v1.gsd"), {"PROFIsafe v1.x Module"}, 0);
    const auto v2 = app::load_gsd_station(corpus("f_module_v2.gsd"), {}, 0);
    options.station.bus = rs4sim::dp::master::BusParameters::defaults_for(rs4sim::dp::BaudRate::k12M);
    for (int a = 0; a <= 125; ++a) {
      if (a == 1) continue;  // the master's
      auto s = a % 2 == 0 ? v1 : v2;
      s.address = static_cast<std::uint8_t>(a);
      if (!profisafe) s.setup.f_parameters.clear();
      options.gsd_slaves.push_back(std::move(s));
    }
    service = std::make_unique<app::MasterService>(options, app::LinkKind::kMemory, out);
    bus = std::make_unique<rs4sim::dp::link::MemoryBus>(clock);
    for (auto* s : service->stations()) bus->attach(*s);
    for (const auto& spec : options.gsd_slaves) {
      stations.push_back(std::make_unique<app::GsdStation>(spec));
      bus->attach(*stations.back());
    }
    service->start(clock.now());
    bus->start();
  }
  NullBuffer null;
  std::ostream out{&null};
  rs4sim::dp::ManualClock clock;
  app::MasterServiceOptions options;
  std::unique_ptr<app::MasterService> service;
  std::unique_ptr<rs4sim::dp::link::MemoryBus> bus;
  std::vector<std::unique_ptr<app::GsdStation>> stations;
};

// Each iteration: 100 ms of simulated time. sim_s_per_wall_s: simulated seconds per wall second.
void BM_GsdFBus125(benchmark::State& state) {
  const bool profisafe = state.range(0) != 0;
  FBus125 b(profisafe);
  b.bus->run_for(2s);  // start-up: every slave in data exchange, every F-host in RUN
  if (!b.service->healthy()) {
    state.SkipWithError("not all 125 GSD slaves in data exchange with their F-hosts in RUN");
    return;
  }
  const auto cycles = b.service->station().master().counters().cycles;
  double simulated = 0;
  for (auto _ : state) {
    b.bus->run_for(100ms);
    simulated += 0.1;
  }
  if (!b.service->healthy()) state.SkipWithError("a slave or an F-host fell out while measured");
  const auto done = b.service->station().master().counters().cycles - cycles;
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
  state.counters["cycles_per_sim_s"] = simulated > 0 ? static_cast<double>(done) / simulated : 0;
  state.counters["f_hosts"] = static_cast<double>(b.service->gsd_slaves().f_module_count());
  state.SetLabel(profisafe ? "PROFIsafe V1/V2 F-hosts" : "same bus without PROFIsafe");
}
BENCHMARK(BM_GsdFBus125)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
