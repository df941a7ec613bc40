// Benchmarks of the RS4's RS232 port ([docs/rs232.md]): framing one full 529-value 0x23
// measurement, and the live 0x23 stream at 25 Hz for 100 scanners in one process (CPU per
// scanner-second: scans, 0x23 encode, framing, transmit queue). Figures are reported, never
// asserted.
#include "rs4/adapter/adapter.h"
#include "rs4/protocol/measurement.h"
#include "rs4/protocol/rs232.h"
#include "rs4/protocol/telegram.h"
#include "rs4/rs232/rs232_port.h"
#include "rs4/scanner/parameter_set.h"

#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

namespace rs4sim::rs4::rs232 {
namespace {

using namespace std::chrono_literals;

// Body (CMD, 3 options, 8-byte scan number, window, 529 values) encode + RS232 frame.
void BM_FrameFullMeasurement(benchmark::State& state) {
  std::array<std::uint16_t, protocol::kContourSegments> contour{};
  for (std::size_t i = 0; i < contour.size(); ++i) {
    contour[i] = static_cast<std::uint16_t>(i % 7 == 0 ? 0 : 1000 + 8 * i);  // zeros to stuff
  }
  protocol::TelegramPrefix prefix;
  prefix.options.state = protocol::Option1State::kMeasuring;
  prefix.options.first_field_pair = 1;
  std::vector<std::uint8_t> body;
  std::vector<std::uint8_t> frame;
  std::uint32_t scan = 0;
  for (auto _ : state) {
    body.clear();
    frame.clear();
    (void)protocol::encode_prefix(0x23, prefix, body);
    (void)protocol::encode_measurement_data(++scan, 1, 0, protocol::kMaxSegment, contour, body);
    (void)protocol::frame_rs232(body, frame);
    benchmark::DoNotOptimize(frame.data());
  }
  state.counters["frame_bytes"] = static_cast<double>(frame.size());
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(frame.size()));
}
BENCHMARK(BM_FrameFullMeasurement);

struct Scanner232 {
  explicit Scanner232(const PortOptions& o) : adapter(config()), port(adapter, o) {}
  static adapter::AdapterConfig config() {
    adapter::AdapterConfig c;
    c.scanner.boot_duration = 100ms;
    return c;
  }
  adapter::Adapter adapter;
  Rs232Port port;
};

// 100 RS4s streaming 0x23 over their RS232 ports; one iteration = one simulated second.
// range(0): resolution of the window (4: 133 values at 115 200 baud, every scan fits;
// 1: 529 values at 57 600 baud, the line takes every 5th scan).
void BM_Stream100Scanners(benchmark::State& state) {
  const auto resolution = static_cast<std::uint8_t>(state.range(0));
  PortOptions o;
  o.baud = resolution == 1 ? 57600 : 115200;
  constexpr std::size_t kScanners = 100;
  std::vector<std::unique_ptr<Scanner232>> rs4s;
  stream::TimePoint now{1h};
  for (std::size_t i = 0; i < kScanners; ++i) {
    auto s = std::make_unique<Scanner232>(o);
    auto set = scanner::factory_default();
    set.measurement.resolution = resolution;
    (void)s->adapter.scanner().set_parameters(set, now);
    (void)s->adapter.scanner().edit_scene(now).add(
        scanner::Circle{{0, 2000.0 + 10.0 * static_cast<double>(i)}, 300});
    s->adapter.power_on(now);
    s->port.attach(now);
    rs4s.push_back(std::move(s));
  }
  now += 200ms;
  std::uint64_t frames = 0, bytes = 0;
  for (auto _ : state) {
    const auto end = now + 1s;
    while (now < end) {
      now += 40ms;
      for (auto& s : rs4s) {
        s->port.on_time(now);
        while (auto f = s->port.take_transmit()) {
          ++frames;
          bytes += f->size();
        }
      }
    }
  }
  const auto scanner_seconds = static_cast<double>(state.iterations()) * static_cast<double>(kScanners);
  state.counters["frames_per_scanner_s"] = static_cast<double>(frames) / scanner_seconds;
  state.counters["bytes_per_scanner_s"] = static_cast<double>(bytes) / scanner_seconds;
  state.counters["scanner_seconds"] = benchmark::Counter(
      static_cast<double>(kScanners), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Stream100Scanners)->Arg(4)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rs4sim::rs4::rs232
