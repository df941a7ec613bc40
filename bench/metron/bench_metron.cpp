// Benchmarks of the virtual METRON (issue 11): one slave-mode request decoded, handled and
// its reply encoded (on_bytes + on_time + take_transmit on a manual clock), one
// standard-mode report composed and sent, and memory per device instance (sizeof + heap).
// Figures are reported, never asserted.
#include "bench/baselines.h"
#include "bench/heap_in_use.h"
#include "metron/checksum.h"
#include "metron/device.h"
#include "metron/standard_report.h"

#include <benchmark/benchmark.h>

#include <array>
#include <cstring>
#include <memory>
#include <vector>

using rs4sim::bench::count_device_memory;
using rs4sim::bench::heap_per_object;

namespace rs4sim::metron {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;

// One request/reply: the reply is due 12.3 ms after the request (Equation 3).
void run_requests(benchmark::State& state, Options o, const Bytes& request) {
  Device d(o);
  stream::TimePoint t{1h};
  d.on_time(t);
  std::size_t reply_bytes = 0;
  for (auto _ : state) {
    d.on_bytes(request, t);
    t += 30ms;
    d.on_time(t);
    auto reply = d.take_transmit();
    reply_bytes = reply ? reply->size() : 0;
    benchmark::DoNotOptimize(reply);
  }
  if (reply_bytes == 0) state.SkipWithError("no reply");
  state.counters["reply_bytes"] = static_cast<double>(reply_bytes);
  state.SetItemsProcessed(state.iterations());
}

void BM_SlaveRequestOssdStatus(benchmark::State& state) {
  run_requests(state, Options{}, {0x02, 0x01, 0x0C, 0xF3});
}
BENCHMARK(BM_SlaveRequestOssdStatus);

// #12 Request OSSD status, no node: exactly one request's bytes in (02 01 0C F3), the
// device decodes, handles and encodes, the reply's bytes out (02 03 0C 00 00 F3, both OSSDs
// OFF) [METRON manual "No node"]. Every request must get its 6-byte reply. Compare it with
// the baselines below (same run, same byte count), not as an absolute time.
inline constexpr std::size_t kOssdRequest = 4;
inline constexpr std::size_t kOssdReply = 6;

void BM_WireOssdStatus(benchmark::State& state) {
  const Bytes request{0x02, 0x01, 0x0C, 0xF3};
  Device d(Options{});
  stream::TimePoint t{1h};
  d.on_time(t);
  std::uint64_t wrong_replies = 0;
  for (auto _ : state) {
    d.on_bytes(request, t);
    t += 30ms;  // past the reply's due time, 12.3 ms after the request (Equation 3)
    d.on_time(t);
    auto reply = d.take_transmit();
    if (!reply || reply->size() != kOssdReply) ++wrong_replies;
    benchmark::DoNotOptimize(reply);
  }
  if (wrong_replies != 0) state.SkipWithError("a request without its reply");
  state.counters["bytes_in_out"] = static_cast<double>(kOssdRequest + kOssdReply);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_WireOssdStatus);

// Baselines of the same run that no device code takes part in: the METRON checksum (sum of
// the bytes, complemented) over as many bytes as one request and its reply, and a memcpy of
// those bytes. Arg: the byte count (10: #12 Request OSSD status).
void BM_BaselineChecksum(benchmark::State& state) {
  bench::run_check_baseline(
      state, [](auto bytes) { return checksum(bytes, ChecksumReading::kModulo256); });
}
BENCHMARK(BM_BaselineChecksum)->Arg(static_cast<std::int64_t>(kOssdRequest + kOssdReply));

using bench::BM_BaselineMemcpy;
BENCHMARK(BM_BaselineMemcpy)->Arg(static_cast<std::int64_t>(kOssdRequest + kOssdReply));

void BM_SlaveRequestMeasurements(benchmark::State& state) {
  run_requests(state, Options{}, {0x02, 0x04, 0x0A, 0x01, 0x02, 0x03, 0xEF});
}
BENCHMARK(BM_SlaveRequestMeasurements);

// 255 beams, all-beam status: 32 data bytes packed per request.
void BM_SlaveRequestAllBeams255(benchmark::State& state) {
  Options o;
  o.beams = 255;
  o.node_enabled = true;
  o.node = 5;
  run_requests(state, o, {0x02, 0x05, 0x02, 0x09, 0x00, 0xF6});
}
BENCHMARK(BM_SlaveRequestAllBeams255);

// Standard mode, continuous: one scan cycle composes and sends one report.
void BM_StandardReportPerCycle(benchmark::State& state) {
  Options o;
  o.line_mode = LineMode::kStandard;
  o.format = Format::kDecimal;
  o.separator = true;
  o.checksum = true;
  o.baud = 115200;
  Device d(o);
  stream::TimePoint t{1h};
  d.on_time(t);
  for (auto _ : state) {
    t += o.scan_cycle;
    d.on_time(t);
    auto r = d.take_transmit();
    benchmark::DoNotOptimize(r);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_StandardReportPerCycle);

void BM_MemoryPerMetron(benchmark::State& state) {
  const stream::TimePoint t{1h};
  const auto answered = [&](std::size_t) {
    Options o;
    o.beams = 255;
    auto d = std::make_unique<Device>(o);
    d->on_time(t);
    d->on_bytes(Bytes{0x02, 0x02, 0x09, 0x00, 0xF6}, t);
    d->on_time(t + 30ms);
    (void)d->take_transmit();
    return d;
  };
  count_device_memory<Device>(state, heap_per_object(state, answered));
}
BENCHMARK(BM_MemoryPerMetron)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rs4sim::metron

BENCHMARK_MAIN();
