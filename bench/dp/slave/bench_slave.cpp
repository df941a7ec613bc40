// bench_dp_slave: the cyclic hot path of dp::slave::Slave and its memory footprint.
//   BM_DataExchangeDecodeHandleEncode  wire bytes → fdl::Decoder → Slave (FCB, state,
//                                      outputs, inputs) → fdl::encode; target ≤ 0.5 µs
//   BM_SlaveMemory                     sizeof(Slave) and heap bytes of one instance
#include "dp/fdl/decoder.h"
#include "dp/fdl/telegram.h"
#include "dp/slave/slave.h"
#include "tests/dp/slave/fake_application.h"

#include <benchmark/benchmark.h>

#include <atomic>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

// Counts the bytes requested from the heap (BM_SlaveMemory). gcc's mismatched-new-delete
// check cannot see that operator new below is malloc-based, hence the pragma.
namespace {
std::atomic<std::size_t> g_heap_bytes{0};
}  // namespace
void* operator new(std::size_t n) {
  g_heap_bytes.fetch_add(n, std::memory_order_relaxed);
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

namespace rs4sim::dp {
namespace {

using testing::Bytes;

dp::slave::Config bench_config() {
  dp::slave::Config c;
  c.address = 5;
  c.ident_number = 0x1234;
  c.dpv1 = true;
  return c;
}

struct Sink final : fdl::DecoderSink {
  dp::slave::Slave* slave = nullptr;
  TimePoint now{};
  void on_telegram(const fdl::Telegram& t) override { slave->on_telegram(t, now); }
};

// [docs/references.md#dp-worked-example] start-up frames, then DX frames with FCB 1 / 0
// alternating.
void start_up(fdl::Decoder& dec, Sink& sink) {
  const Bytes frames[] = {
      {0x68, 0x0F, 0x0F, 0x68, 0x85, 0x82, 0x6D, 0x3D, 0x3E, 0x88, 0x0A,
       0x01, 0x0B, 0x12, 0x34, 0x00, 0x80, 0x20, 0x00, 0x73, 0x16},
      {0x68, 0x07, 0x07, 0x68, 0x85, 0x82, 0x5D, 0x3E, 0x3E, 0x10, 0x20, 0x10, 0x16},
  };
  for (const auto& f : frames) {
    dec.feed(f, sink);
    (void)sink.slave->take_transmit();
  }
}

void BM_DataExchangeDecodeHandleEncode(benchmark::State& state) {
  testing::FakeApplication app;
  dp::slave::Slave slave(bench_config(), app);
  fdl::Decoder dec;
  Sink sink;
  sink.slave = &slave;
  start_up(dec, sink);
  if (slave.state() != dp::slave::State::kDataExch) {
    state.SkipWithError("slave did not reach Data_Exch");
    return;
  }
  const Bytes dx[2] = {{0x68, 0x04, 0x04, 0x68, 0x05, 0x02, 0x7D, 0xA5, 0x29, 0x16},
                       {0x68, 0x04, 0x04, 0x68, 0x05, 0x02, 0x5D, 0xA5, 0x09, 0x16}};
  std::vector<std::uint8_t> out;
  out.reserve(fdl::kMaxTelegramSize);
  std::size_t i = 0;
  for (auto _ : state) {
    dec.feed(dx[i & 1], sink);
    auto reply = slave.take_transmit();
    out.clear();
    fdl::encode(*reply, out);
    benchmark::DoNotOptimize(out.data());
    ++i;
  }
  if (app.outputs.size() != i) state.SkipWithError("a DX was not executed");
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  app.outputs.clear();
}
BENCHMARK(BM_DataExchangeDecodeHandleEncode);

void BM_SlaveMemory(benchmark::State& state) {
  testing::FakeApplication app;
  std::size_t heap = 0;
  for (auto _ : state) {
    // The Slave itself lives in a stack buffer so that only its own allocations count.
    alignas(dp::slave::Slave) static unsigned char storage[sizeof(dp::slave::Slave)];
    const std::size_t before = g_heap_bytes.load();
    auto* slave = new (storage) dp::slave::Slave(bench_config(), app);
    heap = g_heap_bytes.load() - before;
    benchmark::DoNotOptimize(slave);
    std::destroy_at(slave);
  }
  state.counters["sizeof_bytes"] = static_cast<double>(sizeof(dp::slave::Slave));
  state.counters["heap_bytes"] = static_cast<double>(heap);
}
BENCHMARK(BM_SlaveMemory);

}  // namespace
}  // namespace rs4sim::dp
