#pragma once
// The same-run baselines the device benchmarks report their ratios against: work no device
// code takes part in, over as many bytes as one request and its reply. A ratio to them
// survives a slower or busier machine; an absolute time does not.

#include <benchmark/benchmark.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>

namespace rs4sim::bench {

// 64 bytes of a fixed pattern (i × 37: no two neighbours equal).
inline std::array<std::uint8_t, 64> pattern_bytes() {
  std::array<std::uint8_t, 64> bytes{};
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<std::uint8_t>(i * 37U);
  return bytes;
}

// Times `check(first state.range(0) pattern bytes)`: the device's CRC or checksum alone.
template <typename Check>
void run_check_baseline(benchmark::State& state, Check check) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto bytes = pattern_bytes();
  for (auto _ : state) {
    benchmark::DoNotOptimize(bytes.data());
    benchmark::DoNotOptimize(check(std::span<const std::uint8_t>(bytes.data(), n)));
  }
  state.SetItemsProcessed(state.iterations());
}

// A memcpy of state.range(0) bytes (mostly the loop's own cost: the floor of a ratio).
inline void BM_BaselineMemcpy(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  std::array<std::uint8_t, 64> from{};
  std::array<std::uint8_t, 64> to{};
  for (auto _ : state) {
    benchmark::DoNotOptimize(from.data());
    std::memcpy(to.data(), from.data(), n);
    benchmark::DoNotOptimize(to.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations());
}

}  // namespace rs4sim::bench
