// Hot paths of the RS4 wire formats: the measurement telegram 0x23 a scanner produces
// every 40 ms ([RS4 manual §5.2.3.4]), RS232 framing/deframing ([roboticslibrary/rl LeuzeRs4.cpp])
// and the block splitter/assembler ([RS4 manual §5.2.1]). Results are reported, never asserted.
#include "rs4/protocol/block.h"
#include "rs4/protocol/measurement.h"
#include "rs4/protocol/rs232.h"
#include "rs4/protocol/telegram.h"

#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <vector>

namespace {

using namespace rs4sim::rs4::protocol;

std::array<std::uint16_t, kContourSegments> make_contour() {
  std::array<std::uint16_t, kContourSegments> contour{};
  for (std::size_t i = 0; i < contour.size(); ++i) {
    // 1..4 m with some zeros (no echo) and field-violation flags
    const auto distance = static_cast<std::uint16_t>(i % 37 == 0 ? 0 : 1000 + (i * 53) % 3000);
    contour[i] = measurement_value(distance, i % 50 == 7);
  }
  return contour;
}

std::vector<std::uint8_t> measurement_body(std::uint8_t resolution) {
  const auto contour = make_contour();
  std::vector<std::uint8_t> body;
  TelegramPrefix prefix;
  prefix.options.state = Option1State::kMeasuring;
  prefix.options.first_field_pair = 1;
  (void)encode_prefix(static_cast<std::uint8_t>(TelegramCode::kMess16Rt), prefix, body);
  (void)encode_measurement_data(1, resolution, 0, kMaxSegment, contour, body);
  return body;
}

// Encoding a whole 0x23 telegram from the scanner's 529-segment contour.
void BM_MeasurementFromContour(benchmark::State& state) {
  const auto resolution = static_cast<std::uint8_t>(state.range(0));
  const auto contour = make_contour();
  TelegramPrefix prefix;
  prefix.options.state = Option1State::kMeasuring;
  prefix.options.first_field_pair = 1;
  std::vector<std::uint8_t> body;
  std::uint32_t scan = 0;
  for (auto _ : state) {
    body.clear();
    (void)encode_prefix(static_cast<std::uint8_t>(TelegramCode::kMess16Rt), prefix, body);
    (void)encode_measurement_data(++scan, resolution, 0, kMaxSegment, contour, body);
    benchmark::DoNotOptimize(body.data());
  }
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(body.size()));
  state.counters["values"] =
      static_cast<double>(measurement_value_count(0, kMaxSegment, resolution).value());
  state.counters["bytes"] = static_cast<double>(body.size());
}
BENCHMARK(BM_MeasurementFromContour)->Arg(1)->Arg(4);  // 529 values; 133 values
                                                       // ([RS4 manual §5.2.3.4])

void BM_MeasurementDecode(benchmark::State& state) {
  const auto body = measurement_body(static_cast<std::uint8_t>(state.range(0)));
  for (auto _ : state) {
    auto t = decode_telegram(body);
    benchmark::DoNotOptimize(t);
  }
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(body.size()));
}
BENCHMARK(BM_MeasurementDecode)->Arg(1)->Arg(4);

void BM_Rs232Frame(benchmark::State& state) {
  const auto body = measurement_body(static_cast<std::uint8_t>(state.range(0)));
  std::vector<std::uint8_t> wire;
  for (auto _ : state) {
    wire.clear();
    (void)frame_rs232(body, wire);
    benchmark::DoNotOptimize(wire.data());
  }
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(body.size()));
}
BENCHMARK(BM_Rs232Frame)->Arg(1)->Arg(4);

// Deframing a stream of 25 measurement frames (one second of scans at 40 ms) fed in
// 64-byte chunks, as a serial port hands them over.
void BM_Rs232Deframe(benchmark::State& state) {
  const auto body = measurement_body(static_cast<std::uint8_t>(state.range(0)));
  std::vector<std::uint8_t> stream;
  for (int i = 0; i < 25; ++i) (void)frame_rs232(body, stream);
  std::vector<Rs232Deframer::Event> events;
  Rs232Deframer deframer;
  for (auto _ : state) {
    events.clear();
    for (std::size_t at = 0; at < stream.size(); at += 64) {
      const auto chunk = std::min<std::size_t>(64, stream.size() - at);
      deframer.feed(std::span(stream).subspan(at, chunk), events);
    }
    benchmark::DoNotOptimize(events.data());
  }
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(stream.size()));
}
BENCHMARK(BM_Rs232Deframe)->Arg(1)->Arg(4);

// A 1099-byte command through the WRITE assembler (5 blocks) and a 1071-byte answer
// (full 0x23 at resolution 1) through the READ splitter.
void BM_BlockAssemble(benchmark::State& state) {
  const std::vector<std::uint8_t> command(kMaxCommandSize, 0x42);
  auto blocks = split_into_blocks(command, {true, false, FlowState::kNormal});
  for (auto& b : blocks) b[0] = 0x00;  // the master writes flow byte 0
  BlockAssembler assembler;
  for (auto _ : state) {
    for (const auto& b : blocks) benchmark::DoNotOptimize(assembler.push(b));
  }
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(command.size()));
}
BENCHMARK(BM_BlockAssemble);

void BM_BlockSplit(benchmark::State& state) {
  const auto body = measurement_body(1);
  for (auto _ : state) {
    BlockSplitter splitter(body);
    while (!splitter.done()) {
      benchmark::DoNotOptimize(splitter.next({true, false, FlowState::kNormal}));
    }
  }
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(body.size()));
}
BENCHMARK(BM_BlockSplit);

}  // namespace
