// codec::Reader / codec::Appender against hand-written shifts on the same bytes: the
// bounds checks and the latched error should cost nothing measurable.
//   build/bench/codec/bench_codec --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include "codec/reader.h"
#include "codec/writer.h"

#include <benchmark/benchmark.h>
#include <boost/container/static_vector.hpp>

#include <array>
#include <cstdint>
#include <numeric>

namespace {

using rs4sim::codec::Appender;
using rs4sim::codec::Reader;

// A DPV1-sized record: 120 big-endian 16-bit values (240 bytes, the Read.res maximum).
constexpr std::size_t kValues = 120;
std::array<std::uint8_t, 2 * kValues> record() {
  std::array<std::uint8_t, 2 * kValues> b{};
  std::iota(b.begin(), b.end(), std::uint8_t{1});
  return b;
}

void BM_ReadU16BeHandWritten(benchmark::State& state) {
  const auto bytes = record();
  for (auto _ : state) {
    benchmark::DoNotOptimize(bytes.data());
    std::uint32_t sum = 0;
    for (std::size_t i = 0; i + 1 < bytes.size(); i += 2) {
      sum += static_cast<std::uint16_t>((bytes[i] << 8) | bytes[i + 1]);
    }
    benchmark::DoNotOptimize(sum);
  }
}
BENCHMARK(BM_ReadU16BeHandWritten);

void BM_ReadU16BeReader(benchmark::State& state) {
  const auto bytes = record();
  for (auto _ : state) {
    benchmark::DoNotOptimize(bytes.data());
    Reader r(bytes);
    std::uint32_t sum = 0;
    for (std::size_t i = 0; i < kValues; ++i) sum += r.u16_be();
    benchmark::DoNotOptimize(sum);
    benchmark::DoNotOptimize(r.ok());
  }
}
BENCHMARK(BM_ReadU16BeReader);

void BM_ReadU16BeReaderArray(benchmark::State& state) {
  const auto bytes = record();
  std::array<std::uint16_t, kValues> values{};
  for (auto _ : state) {
    benchmark::DoNotOptimize(bytes.data());
    Reader r(bytes);
    r.u16_be_array(values);
    benchmark::DoNotOptimize(std::accumulate(values.begin(), values.end(), 0U));
    benchmark::DoNotOptimize(r.ok());
  }
}
BENCHMARK(BM_ReadU16BeReaderArray);

// A short header of mixed fields, as in a DPV1 request: slot, index, length, u16, u32.
constexpr std::array<std::uint8_t, 9> kHeader{0x5E, 0x01, 0x02, 0x03, 0x12, 0x34, 0xDE, 0xAD, 0xBE};

void BM_ReadHeaderHandWritten(benchmark::State& state) {
  auto bytes = kHeader;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bytes.data());
    if (bytes.size() < 9) continue;
    const std::uint32_t v = static_cast<std::uint32_t>(bytes[1] + bytes[2] + bytes[3]) +
                            static_cast<std::uint16_t>((bytes[4] << 8) | bytes[5]) +
                            ((static_cast<std::uint32_t>(bytes[6]) << 16) |
                             static_cast<std::uint32_t>(bytes[7] << 8) | bytes[8]);
    benchmark::DoNotOptimize(v);
  }
}
BENCHMARK(BM_ReadHeaderHandWritten);

void BM_ReadHeaderReader(benchmark::State& state) {
  auto bytes = kHeader;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bytes.data());
    Reader r(bytes);
    r.skip(1);
    std::uint32_t v = static_cast<std::uint32_t>(r.u8() + r.u8() + r.u8() + r.u16_be());
    v += static_cast<std::uint32_t>(r.u8()) << 16;
    v += r.u16_be();
    benchmark::DoNotOptimize(v);
    benchmark::DoNotOptimize(r.ok());
  }
}
BENCHMARK(BM_ReadHeaderReader);

using Du = boost::container::static_vector<std::uint8_t, 246>;

void BM_WriteU16BeHandWritten(benchmark::State& state) {
  Du out;
  for (auto _ : state) {
    out.clear();
    for (std::size_t i = 0; i < kValues; ++i) {
      const auto v = static_cast<std::uint16_t>(i * 257U);
      if (out.size() + 2 > 244) break;
      out.push_back(static_cast<std::uint8_t>(v >> 8));
      out.push_back(static_cast<std::uint8_t>(v & 0xFFU));
    }
    benchmark::DoNotOptimize(out.data());
  }
}
BENCHMARK(BM_WriteU16BeHandWritten);

void BM_WriteU16BeAppender(benchmark::State& state) {
  Du out;
  for (auto _ : state) {
    out.clear();
    Appender w(out, 244);
    for (std::size_t i = 0; i < kValues; ++i) w.u16_be(static_cast<std::uint16_t>(i * 257U));
    benchmark::DoNotOptimize(out.data());
    benchmark::DoNotOptimize(w.ok());
  }
}
BENCHMARK(BM_WriteU16BeAppender);

}  // namespace
