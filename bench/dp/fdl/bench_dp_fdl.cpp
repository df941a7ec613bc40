// FDL codec hot paths ([IEC 61158-4-3 frame formats]): one Data_Exchange request decoded and
// one response encoded (SD2, 6 data bytes), the slave's decode→reply→encode step (with its
// speed-up over pyprofibus), the streaming decoder's throughput, and the PDU decoders used
// at start-up. The same telegrams in Python: bench/dp/fdl/pyprofibus_fdl_bench.py.
#include "dp/fdl/decoder.h"
#include "dp/fdl/fcb.h"
#include "dp/pdu/cfg.h"
#include "dp/pdu/dpv1.h"
#include "dp/pdu/set_prm.h"

#include <benchmark/benchmark.h>

#include <array>
#include <cstdlib>
#include <vector>

namespace {

using namespace rs4sim::dp;

std::vector<std::uint8_t> frame_of(const fdl::Telegram& t) {
  std::vector<std::uint8_t> out;
  fdl::encode(t, out);
  return out;
}

const std::array<std::uint8_t, 6> kOutputs = {0x11, 0x22, 0x33, 0x44, 0x55, 0x66};

fdl::Telegram dx_request() {
  return fdl::make_data_telegram(
      5, 2, fdl::FrameControl::request(fdl::RequestFunction::kSrdHigh, true, true), std::nullopt,
      std::nullopt, kOutputs);
}

fdl::Telegram dx_response() {
  return fdl::make_data_telegram(2, 5, fdl::FrameControl::response(fdl::ResponseStatus::kDataLow),
                                 std::nullopt, std::nullopt, kOutputs);
}

// pyprofibus' FDL layer on the same two telegrams, CPU ns per decode+encode, measured by
// bench/dp/fdl/pyprofibus_fdl_bench.py (figure and machine in dp/fdl/README.md); set
// PYPROFIBUS_NS to the figure that script prints on the machine at hand.
constexpr double kPyprofibusNs = 2460;

double pyprofibus_ns() {
  const char* env = std::getenv("PYPROFIBUS_NS");
  const double ns = env != nullptr ? std::strtod(env, nullptr) : 0.0;
  return ns > 0.0 ? ns : kPyprofibusNs;
}

class CountSink final : public fdl::DecoderSink {
 public:
  void on_telegram(const fdl::Telegram& t) override {
    ++telegrams;
    benchmark::DoNotOptimize(t.data.data());
  }
  std::size_t telegrams = 0;
};

void BM_DecodeDataExchangeRequest(benchmark::State& state) {
  const auto frame = frame_of(dx_request());
  fdl::Decoder d;
  CountSink sink;
  for (auto _ : state) d.feed(frame, sink);
  if (sink.telegrams != static_cast<std::size_t>(state.iterations()))
    state.SkipWithError("lost telegrams");
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(frame.size()));
}
BENCHMARK(BM_DecodeDataExchangeRequest);

void BM_EncodeDataExchangeResponse(benchmark::State& state) {
  const fdl::Telegram reply = dx_response();
  std::array<std::uint8_t, fdl::kMaxTelegramSize> out{};
  for (auto _ : state) {
    benchmark::DoNotOptimize(fdl::encode(reply, std::span<std::uint8_t>(out)));
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_EncodeDataExchangeResponse);

// The codec share of the slave's ≤ 0.5 µs budget: decode the request, FCB check, fill
// the reply's input image, encode it.
class ReplySink final : public fdl::DecoderSink {
 public:
  void on_telegram(const fdl::Telegram& t) override {
    if (fcb.on_request(t.sa, t.fc) == fdl::FcbVerdict::kRepeat) return;
    reply.da = t.sa;
    reply.sa = t.da;
    reply.data = t.data;
    written += fdl::encode(reply, std::span<std::uint8_t>(out));
  }
  fdl::FcbResponder fcb;
  fdl::Telegram reply = dx_response();
  std::array<std::uint8_t, fdl::kMaxTelegramSize> out{};
  std::size_t written = 0;
};

void BM_DecodeReplyEncodeDataExchange(benchmark::State& state) {
  fdl::Telegram req = dx_request();
  const auto even = frame_of(req);
  req.fc = fdl::FrameControl::request(fdl::RequestFunction::kSrdHigh, false, true);
  const auto odd = frame_of(req);
  fdl::Decoder d;
  ReplySink sink;
  bool toggle = false;
  for (auto _ : state) {
    d.feed(toggle ? odd : even, sink);  // FCB toggles like a real master
    toggle = !toggle;
  }
  benchmark::DoNotOptimize(sink.written);
  // Speed-up over pyprofibus on the same telegrams: Google Benchmark divides a rate
  // counter by the CPU time per iteration, so "x_pyprofibus=N/s" reads as N times faster.
  state.counters["x_pyprofibus"] =
      benchmark::Counter(pyprofibus_ns() * 1e-9, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_DecodeReplyEncodeDataExchange);

// A realistic bus mix: DX request/reply, Slave_Diag, SC, token, in 256-byte chunks.
void BM_StreamThroughput(benchmark::State& state) {
  std::vector<std::uint8_t> stream;
  while (stream.size() < 64 * 1024) {
    for (const auto& t :
         {dx_request(), dx_response(), fdl::make_short_ack(), fdl::make_token(2, 2)}) {
      const auto f = frame_of(t);
      stream.insert(stream.end(), f.begin(), f.end());
    }
    const std::uint8_t diag[] = {0x68, 0x0B, 0x0B, 0x68, 0x82, 0x85, 0x08, 0x3E, 0x3C,
                                 0x02, 0x05, 0x00, 0xFF, 0x12, 0x34, 0xD5, 0x16};
    stream.insert(stream.end(), std::begin(diag), std::end(diag));
  }
  const auto chunk = static_cast<std::size_t>(state.range(0));
  fdl::Decoder d;
  CountSink sink;
  for (auto _ : state) {
    for (std::size_t pos = 0; pos < stream.size(); pos += chunk) {
      d.feed(
          std::span<const std::uint8_t>(stream).subspan(pos, std::min(chunk, stream.size() - pos)),
          sink);
    }
  }
  if (d.stats().total_errors() != 0) state.SkipWithError("decode errors");
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(stream.size()));
}
BENCHMARK(BM_StreamThroughput)->Arg(1)->Arg(16)->Arg(256)->Arg(4096);

void BM_DecodeSetPrm(benchmark::State& state) {
  const std::array<std::uint8_t, 10> du = {0x88, 0x0A, 0x01, 0x0B, 0x12,
                                           0x34, 0x00, 0x80, 0x20, 0x00};
  for (auto _ : state) benchmark::DoNotOptimize(pdu::decode_set_prm(du, pdu::PrmLayout::kDpv1));
}
BENCHMARK(BM_DecodeSetPrm);

void BM_SummarizeChkCfg(benchmark::State& state) {
  const std::array<std::uint8_t, 9> du = {0x10, 0x20, 0xC4, 0x84, 0x84, 0x05, 0x0A, 0x05, 0x0A};
  for (auto _ : state) benchmark::DoNotOptimize(pdu::summarize_cfg(du, pdu::CfgService::kChkCfg));
}
BENCHMARK(BM_SummarizeChkCfg);

void BM_DecodeC1ReadRequest(benchmark::State& state) {
  const std::array<std::uint8_t, 4> du = {0x5E, 0x00, 0x01, 0x10};
  for (auto _ : state) benchmark::DoNotOptimize(pdu::decode_c1_request(du));
}
BENCHMARK(BM_DecodeC1ReadRequest);

}  // namespace
