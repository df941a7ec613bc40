// The cyclic path (decode one Data_Exchange request, encode the reply) must not touch
// the heap. This binary replaces the global operator new to count allocations.
#include "dp/fdl/decoder.h"
#include "dp/fdl/fcb.h"

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace rs4sim::dp::fdl {
namespace {

class ReplySink final : public DecoderSink {
 public:
  void on_telegram(const Telegram& t) override {
    fcb.on_request(t.sa, t.fc);
    reply.da = t.sa;
    reply.sa = t.da;
    reply.data = t.data;
    written += encode(reply, out);
  }
  FcbResponder fcb;
  Telegram reply =
      make_data_telegram(2, 5, FrameControl::response(ResponseStatus::kDataLow), std::nullopt,
                         std::nullopt, std::array<std::uint8_t, 1>{0x3C});
  std::array<std::uint8_t, kMaxTelegramSize> out{};
  std::size_t written = 0;
};

TEST(FdlAlloc, DecodeAndEncodeDataExchangeWithoutHeap) {
  // [docs/references.md#dp-worked-example] DX request with 6 output bytes (FCS computed over
  // DA..DU).
  std::array<std::uint8_t, 15> dx = {0x68, 0x09, 0x09, 0x68, 0x05, 0x02, 0x7D, 1,
                                     2,    3,    4,    5,    6,    0,    0x16};
  unsigned sum = 0;
  for (std::size_t i = 4; i < 13; ++i) sum += dx[i];
  dx[13] = static_cast<std::uint8_t>(sum);
  auto decoder = std::make_unique<Decoder>();
  auto sink = std::make_unique<ReplySink>();
  const long before = g_allocations.load();
  for (int i = 0; i < 1000; ++i) decoder->feed(dx, *sink);
  const long after = g_allocations.load();
  EXPECT_EQ(after - before, 0);
  EXPECT_EQ(decoder->stats().telegrams, 1000U);
  EXPECT_EQ(sink->written, 1000U * 15U);
}

}  // namespace
}  // namespace rs4sim::dp::fdl
