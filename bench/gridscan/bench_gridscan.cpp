// Benchmarks of the virtual GridScan/Pro SI (issue 11): decode + handle + encode per
// request (the whole device path: idle-gap framing, checks, command, answer frame with
// CRC-32) and the memory of one device instance (sizeof + heap). Figures are reported,
// never asserted.
#include "bench/baselines.h"
#include "bench/heap_in_use.h"
#include "gridscan/crc32_mpeg2.h"
#include "gridscan/device.h"
#include "stream/memory_line.h"

#include <benchmark/benchmark.h>

#include <array>
#include <cstring>
#include <memory>
#include <vector>

using rs4sim::bench::count_device_memory;
using rs4sim::bench::heap_per_object;

namespace rs4sim::gridscan {
namespace {

using namespace std::chrono_literals;

// One request → answer through the device: on_bytes, the idle gap, the cycle end, the
// answer taken. The clock jumps a cycle per request (no real waiting).
// The curtain powered up and its power-up messages taken: ready for requests at `t`.
void power_up(Device& d, stream::TimePoint& t) {
  d.on_time(t);
  t += 2s;
  d.on_time(t);
  while (d.take_transmit()) {
  }
}

void run_requests(benchmark::State& state, CommandId id, unsigned elements) {
  Options o;
  o.elements = elements;
  Device d(o);
  stream::TimePoint t{1h};
  power_up(d, t);
  std::uint8_t seq = 2;
  std::size_t bytes = 0;
  for (auto _ : state) {
    const auto request = encode(Frame{seq, request_id(id), {}});
    d.on_bytes(request, t);
    t += o.cycle_time();
    d.on_time(t);
    auto answer = d.take_transmit();
    bytes += answer ? answer->size() : 0;
    benchmark::DoNotOptimize(answer);
    seq = static_cast<std::uint8_t>(seq + 2);
  }
  state.counters["answered"] = static_cast<double>(d.counters().answered);
  state.SetItemsProcessed(state.iterations());
  state.SetBytesProcessed(static_cast<std::int64_t>(bytes));
}

void BM_RequestFullState60(benchmark::State& s) { run_requests(s, CommandId::kDataFullState, 60); }
void BM_RequestReducedState22(benchmark::State& s) {
  run_requests(s, CommandId::kDataReducedState, 22);
}
void BM_RequestCommTest(benchmark::State& s) {
  run_requests(s, CommandId::kInfoCommunicationTest, 22);
}
BENCHMARK(BM_RequestFullState60);
BENCHMARK(BM_RequestReducedState22);
BENCHMARK(BM_RequestCommTest);

// One request's bytes in, the reply's bytes out, nothing else in the loop: the requests are
// sealed before the timing (one per sequence counter, 128 in turn, each the previous
// answer's SeqCnt + 1 [GridScan manual §9.2.2]), so the loop times the device alone:
// on_bytes (idle-gap framing), on_time at the cycle end (inspect, checks, command, answer
// frame with CRC-32), take_transmit. Every request must be answered with `reply_size` bytes.
// Compare it with the baselines below (same run, same byte count), not as an absolute time.
void run_wire_requests(benchmark::State& state, CommandId id, unsigned elements,
                       std::size_t reply_size) {
  std::vector<std::vector<std::uint8_t>> requests;
  requests.reserve(128);
  for (unsigned i = 0; i < 128; ++i) {
    const auto seq = static_cast<std::uint8_t>(2U + 2U * i);
    requests.push_back(encode(Frame{seq, request_id(id), {}}));
  }
  Options o;
  o.elements = elements;
  Device d(o);
  stream::TimePoint t{1h};
  power_up(d, t);
  const auto cycle = o.cycle_time();
  std::size_t next = 0;
  std::uint64_t wrong_replies = 0;
  for (auto _ : state) {
    d.on_bytes(requests[next], t);
    t += cycle;
    d.on_time(t);
    auto reply = d.take_transmit();
    if (!reply || reply->size() != reply_size) ++wrong_replies;
    benchmark::DoNotOptimize(reply);
    next = (next + 1) % requests.size();
  }
  if (wrong_replies != 0) state.SkipWithError("a request without its reply");
  state.counters["bytes_in_out"] = static_cast<double>(kMinFrame + reply_size);
  state.SetItemsProcessed(state.iterations());
}

// 0x23 Info: Communication test, its answer one byte of payload: 10 + 11 bytes.
inline constexpr std::size_t kCommTestReply = kMinFrame + 1;
// 0x30 Data: Reduced state, 22 elements: 10 + 12 bytes (two bytes of payload).
inline constexpr std::size_t kReducedStateReply = kMinFrame + 2;

void BM_WireCommTest(benchmark::State& s) {
  run_wire_requests(s, CommandId::kInfoCommunicationTest, 22, kCommTestReply);
}
void BM_WireReducedState22(benchmark::State& s) {
  run_wire_requests(s, CommandId::kDataReducedState, 22, kReducedStateReply);
}
BENCHMARK(BM_WireCommTest);
BENCHMARK(BM_WireReducedState22);

// Baselines of the same run that no device code takes part in: the CRC-32 over as many
// bytes as one request and its reply (the request's and the reply's CRC together), and a
// memcpy of those bytes. Arg: the byte count (21: communication test, 22: reduced state).
void BM_BaselineCrc32(benchmark::State& state) {
  bench::run_check_baseline(state, [](auto bytes) { return crc32_mpeg2(bytes); });
}
BENCHMARK(BM_BaselineCrc32)
    ->Arg(static_cast<std::int64_t>(kMinFrame + kCommTestReply))
    ->Arg(static_cast<std::int64_t>(kMinFrame + kReducedStateReply));

using bench::BM_BaselineMemcpy;
BENCHMARK(BM_BaselineMemcpy)
    ->Arg(static_cast<std::int64_t>(kMinFrame + kCommTestReply))
    ->Arg(static_cast<std::int64_t>(kMinFrame + kReducedStateReply));

// The same request through the simulated line (`--link memory`'s stream::MemoryLine, as an
// Exchange runs it, without gRPC): the request's wire time, the idle gap, the cycle end, the
// answer's wire time, all on the manual clock.
void BM_RequestCommTestOnMemoryLine(benchmark::State& state) {
  stream::ManualClock clock;
  Device d{Options{}};
  stream::MemoryLine line(clock, d);
  line.start();
  line.run_for(2s);
  (void)line.take_received();
  std::uint8_t seq = 2;
  std::size_t answered = 0;
  for (auto _ : state) {
    line.write(encode(Frame{seq, request_id(CommandId::kInfoCommunicationTest), {}}));
    line.run_for(31ms);  // one cycle and the answer's wire time
    answered += line.take_received().size();
    seq = static_cast<std::uint8_t>(seq + 2);
  }
  state.counters["answered"] = static_cast<double>(answered);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_RequestCommTestOnMemoryLine);

// The codec alone: encode a 20-byte frame, then decode it strictly.
void BM_FrameEncodeDecode(benchmark::State& state) {
  const Frame f{3, 0xA0, {0x30, 0x31, 0x2E, 0x30, 0x32, 0x30, 0x33, 0x2E, 0x30, 0x34}};
  for (auto _ : state) {
    const auto bytes = encode(f);
    auto back = decode_response(bytes, 22);
    benchmark::DoNotOptimize(back);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_FrameEncodeDecode);

// Memory of N booted devices, per device.
void BM_MemoryPerDevice(benchmark::State& state) {
  const stream::TimePoint t{1h};
  const auto booted = [&](std::size_t) {
    auto d = std::make_unique<Device>(Options{});
    d->on_time(t);
    d->on_time(t + 2s);  // ready
    while (d->take_transmit()) {
    }
    return d;
  };
  // The vector's array excluded.
  count_device_memory<Device>(state, heap_per_object(state, booted, true));
}
BENCHMARK(BM_MemoryPerDevice)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rs4sim::gridscan

BENCHMARK_MAIN();
