// How long the master's start-up spends on the GSD: parse the shipped file, configure
// the RS4 module with overrides (incl. CRC1), decode Cfg identifiers.
#include "gsd/cfg.h"
#include "gsd/config.h"
#include "gsd/device_gsd.h"
#include "gsd/interp.h"

#include <benchmark/benchmark.h>

#include <string>

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

// A modular station with `n` modules of one Cfg byte each (the file of a hostile or generated
// GSD): parsing stays linear in the file's size (100k modules: about 10 MB of statements).
std::string many_modules(std::int64_t n) {
  std::string text =
      "#Profibus_DP\nIdent_Number = 0x1234\n12M_supp = 1\nMaxTsdr_12M = 800\n"
      "Modular_Station = 1\nMax_Module = 244\n";
  for (std::int64_t i = 0; i < n; ++i) {
    text += "Module = \"Module " + std::to_string(i) + "\" 0x10\nEndModule\n";
  }
  return text;
}

void BM_ParseManyModules(benchmark::State& state) {
  const std::string text = many_modules(state.range(0));
  for (auto _ : state) {
    auto device = parse(text, "many.gsd");
    if (!device || device.value().modules.size() != static_cast<std::size_t>(state.range(0))) {
      state.SkipWithError("not parsed");
    }
    benchmark::DoNotOptimize(device);
  }
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(text.size()));
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_ParseManyModules)
    ->RangeMultiplier(10)
    ->Range(1000, 100000)
    ->Unit(benchmark::kMillisecond)
    ->Complexity(benchmark::oN);

// The last module of such a file configured by name (what `rs4sim gsd --prm --module` does).
void BM_ConfigureLastOfManyModules(benchmark::State& state) {
  const auto device = parse(many_modules(state.range(0)), "many.gsd");
  const ConfigRequest request{{"Module " + std::to_string(state.range(0) - 1)}, {}};
  for (auto _ : state) {
    auto config = configure(device.value(), request);
    benchmark::DoNotOptimize(config);
  }
}
BENCHMARK(BM_ConfigureLastOfManyModules)->Arg(100000)->Unit(benchmark::kMillisecond);

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
