// Benchmarks of the Polaris barrier (figures in docs/polaris.md, reported, not asserted):
// one Modbus request decoded, handled and its answer encoded (on_bytes, on_time at the
// deadlines, take_transmit) per data mode; a master push; memory per device instance
// (sizeof + the heap it holds, from glibc's allocator statistics, as counters).
#include "bench/baselines.h"
#include "modbus/crc16.h"
#include "modbus/pdu.h"
#include "modbus/rtu_frame.h"
#include "polaris/device.h"

#include <benchmark/benchmark.h>

#include <malloc.h>

#include <array>
#include <chrono>
#include <cstring>
#include <memory>
#include <optional>

namespace {

using namespace rs4sim;
using std::chrono::milliseconds;

polaris::Options options(polaris::DataMode mode, std::uint16_t beams) {
  polaris::Options o;
  o.family = polaris::Family::kPli02;
  o.beams = beams;
  o.mode = mode;
  o.response_time = std::chrono::microseconds(500);
  return o;
}

std::vector<std::uint16_t> typical_scene() { return {9, 10, 11, 12, 13, 25, 26, 27, 34, 90}; }

std::vector<std::uint8_t> request(polaris::DataMode mode, std::uint16_t beams) {
  const auto words = mode == polaris::DataMode::k485Mb
                         ? static_cast<std::uint16_t>((beams + 15) / 16)
                         : std::uint16_t{10};
  return modbus::encode(
      modbus::make_read_request(1, {modbus::kReadHoldingRegisters, 0x2000, words}));
}

// The slave started at `now` with the typical scene.
void start_with_scene(polaris::Device& device, stream::TimePoint now) {
  device.on_time(now);
  (void)device.set_interrupted(typical_scene(), now);
}

// One request through the device: its bytes in at `now`, every deadline served (the framer's
// t3.5, the scan's end), the answer out; `now` ends 1 ms after the last deadline.
std::optional<std::vector<std::uint8_t>> one_request(polaris::Device& device,
                                                     const std::vector<std::uint8_t>& req,
                                                     stream::TimePoint& now) {
  device.on_bytes(req, now);
  while (auto next = device.next_deadline()) {
    now = *next;
    device.on_time(now);
  }
  auto answer = device.take_transmit();
  now += milliseconds(1);
  return answer;
}

void BM_SlaveRequest(benchmark::State& state) {
  const auto mode = static_cast<polaris::DataMode>(state.range(0));
  const auto beams = static_cast<std::uint16_t>(state.range(1));
  polaris::Device device(options(mode, beams));
  stream::TimePoint now{std::chrono::hours(1)};
  start_with_scene(device, now);
  const std::vector<std::uint8_t> req = request(mode, beams);
  std::size_t answer_bytes = 0;
  for (auto _ : state) {
    auto answer = one_request(device, req, now);
    answer_bytes = answer ? answer->size() : 0;
    benchmark::DoNotOptimize(answer);
  }
  state.counters["answer_bytes"] = static_cast<double>(answer_bytes);
  state.counters["requests/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SlaveRequest)
    ->ArgNames({"mode", "beams"})
    ->Args({static_cast<int>(polaris::DataMode::k485Mb), 127})
    ->Args({static_cast<int>(polaris::DataMode::k485Mb), 1375})
    ->Args({static_cast<int>(polaris::DataMode::kFl1), 127})
    ->Args({static_cast<int>(polaris::DataMode::kFl4), 127})
    ->Args({static_cast<int>(polaris::DataMode::kFl10), 1375});

// FC 3 read of the whole data block, 485MB mode, 127 beams (8 registers): exactly one
// request's bytes in (8), the device decodes, handles and encodes, the answer's bytes out
// (3 + 16 + 2 = 21) [Modbus application protocol V1.1b3 §6.3]. The same path as
// BM_SlaveRequest/mode:0/beams:127, with every request's answer checked. Compare it with
// the baselines below (same run, same byte count), not as an absolute time.
constexpr std::size_t kFc3Request = 8;
constexpr std::size_t kFc3Answer = 21;

void BM_WireFc3DataBlock(benchmark::State& state) {
  polaris::Device device(options(polaris::DataMode::k485Mb, 127));
  stream::TimePoint now{std::chrono::hours(1)};
  start_with_scene(device, now);
  const std::vector<std::uint8_t> req = request(polaris::DataMode::k485Mb, 127);
  std::uint64_t wrong_answers = 0;
  for (auto _ : state) {
    auto answer = one_request(device, req, now);
    if (!answer || answer->size() != kFc3Answer) ++wrong_answers;
    benchmark::DoNotOptimize(answer);
  }
  if (req.size() != kFc3Request || wrong_answers != 0) {
    state.SkipWithError("a request without its answer");
  }
  state.counters["bytes_in_out"] = static_cast<double>(kFc3Request + kFc3Answer);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_WireFc3DataBlock);

// Baselines of the same run that no device code takes part in: the Modbus CRC-16 over as
// many bytes as one request and its answer (the two frames' CRCs together), and a memcpy of
// those bytes. Arg: the byte count (29: the FC 3 read above).
void BM_BaselineCrc16(benchmark::State& state) {
  bench::run_check_baseline(state, [](auto bytes) { return modbus::crc16(bytes); });
}
BENCHMARK(BM_BaselineCrc16)->Arg(static_cast<std::int64_t>(kFc3Request + kFc3Answer));

using bench::BM_BaselineMemcpy;
BENCHMARK(BM_BaselineMemcpy)->Arg(static_cast<std::int64_t>(kFc3Request + kFc3Answer));

void BM_MasterPush(benchmark::State& state) {
  polaris::Options o = options(polaris::DataMode::kFl4, 127);
  o.role = polaris::Role::kMaster;
  o.scan_time = milliseconds(5);
  polaris::Device device(o);
  stream::TimePoint now{std::chrono::hours(1)};
  device.on_time(now);
  (void)device.set_interrupted(typical_scene(), now);
  for (auto _ : state) {
    now = *device.next_deadline();
    device.on_time(now);
    benchmark::DoNotOptimize(device.take_transmit());
  }
}
BENCHMARK(BM_MasterPush);

void BM_Crc16(benchmark::State& state) {
  const std::vector<std::uint8_t> bytes(254, 0xA5);
  for (auto _ : state) benchmark::DoNotOptimize(modbus::crc16(bytes));
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(bytes.size()));
}
BENCHMARK(BM_Crc16);

// Memory of one device: sizeof + the heap it holds after a scene and a request. The heap
// is glibc's in-use total over kLive devices kept alive at once, divided by kLive (freed
// chunks parked in the thread cache would skew a single allocation's delta).
void BM_DeviceMemory(benchmark::State& state) {
  constexpr std::size_t kLive = 512;
  const auto beams = static_cast<std::uint16_t>(state.range(0));
  double per_device = 0;
  for (auto _ : state) {
    std::vector<std::unique_ptr<polaris::Device>> devices;
    devices.reserve(kLive);
    const std::size_t before = mallinfo2().uordblks;
    for (std::size_t i = 0; i < kLive; ++i) {
      auto& d = devices.emplace_back(
          std::make_unique<polaris::Device>(options(polaris::DataMode::k485Mb, beams)));
      stream::TimePoint now{std::chrono::hours(1)};
      d->on_time(now);
      (void)d->set_interrupted(typical_scene(), now);
      d->on_bytes(request(polaris::DataMode::k485Mb, beams), now);
    }
    per_device = static_cast<double>(mallinfo2().uordblks - before) / kLive;
    benchmark::DoNotOptimize(devices);
  }
  const double heap = per_device - static_cast<double>(sizeof(polaris::Device));
  state.counters["sizeof_bytes"] = static_cast<double>(sizeof(polaris::Device));
  state.counters["heap_bytes"] = heap;
  state.counters["total_KiB"] = per_device / 1024.0;
}
BENCHMARK(BM_DeviceMemory)->Arg(127)->Arg(1375);

}  // namespace
