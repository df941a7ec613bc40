// How long the master's start-up spends on the GSD: parse the shipped file, configure
// the RS4 module with overrides (incl. CRC1), decode Cfg identifiers.
#include "gsd/cfg.h"
#include "gsd/config.h"
#include "gsd/device_gsd.h"
#include "gsd/interp.h"

#include <benchmark/benchmark.h>

namespace {

using namespace rs4sim::gsd;

void BM_SyntaxOnly(benchmark::State& state) {
  for (auto _ : state) {
    auto file = syntax::parse_syntax(rs4sim_gsd_text(), "RSIM5234.gsd");
    benchmark::DoNotOptimize(file);
  }
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(rs4sim_gsd_text().size()));
}
BENCHMARK(BM_SyntaxOnly);

void BM_ParseShippedGsd(benchmark::State& state) {
  for (auto _ : state) {
    auto device = parse(rs4sim_gsd_text(), "RSIM5234.gsd");
    benchmark::DoNotOptimize(device);
  }
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(rs4sim_gsd_text().size()));
}
BENCHMARK(BM_ParseShippedGsd);

void BM_ConfigureRs4WithOverrides(benchmark::State& state) {
  const Device& device = rs4sim_device().value();
  const ConfigRequest request{{},
                              {{"F_Dest_Add", 600}, {"F_WD_Time", 500}, {"F_Source_Add", 2002}}};
  for (auto _ : state) {
    auto config = configure(device, request);
    benchmark::DoNotOptimize(config);
  }
}
BENCHMARK(BM_ConfigureRs4WithOverrides);

void BM_DecodeCfg(benchmark::State& state) {
  const std::vector<std::uint8_t> cfg{0xC4, 0x84, 0x84, 0x05, 0x0A, 0x05,
                                      0x0A, 0x10, 0x20, 0x51, 0xB4};
  for (auto _ : state) {
    auto layout = decode_cfg(cfg);
    benchmark::DoNotOptimize(layout);
  }
}
BENCHMARK(BM_DecodeCfg);

}  // namespace
