// Hot paths of the PROFIsafe layer: one RS4 PDU built and checked (target ≤ 100 ns each),
// the V2 12-byte PDU of the capture, CRC1, and one full host ↔ device cycle.
#include "profisafe/crc.h"
#include "profisafe/f_device.h"
#include "profisafe/f_host.h"
#include "profisafe/pdu.h"

#include <benchmark/benchmark.h>

#include <array>
#include <chrono>
#include <cstdint>

namespace {
using namespace rs4sim::profisafe;

PduConfig rs4_config() {
  PduConfig c;
  c.crc1 = 0x83A9;
  return c;
}

void BM_BuildPduV1Rs4(benchmark::State& state) {
  const PduConfig c = rs4_config();
  std::array<std::uint8_t, kMaxPduSize> out{};
  std::uint8_t data = 0x80, n = 1;
  for (auto _ : state) {
    auto r = build_pdu(c, std::span<const std::uint8_t>(&data, 1), 0x00, n, out);
    benchmark::DoNotOptimize(r);
    benchmark::DoNotOptimize(out);
    n = next_consecutive_number(n);
  }
}
BENCHMARK(BM_BuildPduV1Rs4);

void BM_CheckPduV1Rs4(benchmark::State& state) {
  const PduConfig c = rs4_config();
  const std::array<std::uint8_t, 5> pdu{0x80, 0x00, 0x01, 0x73, 0x0B};
  for (auto _ : state) {
    auto r = check_pdu(c, pdu);
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_CheckPduV1Rs4);

void BM_CheckPduV2Capture(benchmark::State& state) {
  PduConfig c;
  c.version = ProtocolVersion::kV2;
  c.data_size = 8;
  c.crc1 = 0x22FF;
  const std::array<std::uint8_t, 12> pdu{0x41, 0x01, 0x00, 0x04, 0,    0,
                                         0,    0,    0x40, 0xBB, 0x5F, 0xB5};
  for (auto _ : state) {
    auto r = check_pdu(c, pdu, 0);
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_CheckPduV2Capture);

void BM_Crc1(benchmark::State& state) {
  FParameters p;
  for (auto _ : state) {
    benchmark::DoNotOptimize(crc1(p));
    p.wd_time_ms = static_cast<std::uint16_t>(p.wd_time_ms + 1);
  }
}
BENCHMARK(BM_Crc1);

// One bus cycle: host request → device check + response → host check.
void BM_HostDeviceCycle(benchmark::State& state) {
  FHost host(FHostConfig{});
  FDevice dev(FDeviceConfig{DeviceProfile{}, 1, {}});
  (void)dev.set_parameters(host.parameter_block());
  const std::uint8_t in = 0x80;
  dev.set_input(std::span<const std::uint8_t>(&in, 1));
  rs4sim::profisafe::TimePoint now{std::chrono::hours(1)};
  for (auto _ : state) {
    now += std::chrono::milliseconds(1);
    const auto req = host.request(now);
    benchmark::DoNotOptimize(dev.on_pdu(req, now));
    benchmark::DoNotOptimize(host.on_pdu(dev.response(), now));
  }
  if (host.state() != FHostState::kRun) state.SkipWithError("cycle did not reach kRun");
}
BENCHMARK(BM_HostDeviceCycle);

}  // namespace
