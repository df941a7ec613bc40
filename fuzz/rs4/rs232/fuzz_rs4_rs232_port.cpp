// Fuzzes the RS4's RS232 command path end to end: arbitrary bytes in arbitrary chunks into
// a live rs4::rs232::Rs232Port (deframer → interpreter → adapter/scanner), time advancing
// between chunks ([docs/rs232.md]). Checks: every frame the port sends deframes to exactly
// one body that the client decodes; the RS4's set always validates; the switched-through
// bit stays set while attached.
// Input: [chunk length (low 6 bits) | time step selector (high 2 bits)][chunk bytes…] …
#include "rs4/adapter/adapter.h"
#include "rs4/rs232/rs232_client.h"
#include "rs4/rs232/rs232_port.h"
#include "rs4/scanner/parameter_set.h"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <span>

using namespace rs4sim::rs4;
using namespace std::chrono_literals;

namespace {

const rs4sim::stream::TimePoint kStart{std::chrono::hours(1)};

void check(bool ok) {
  if (!ok) __builtin_trap();
}

void check_frames(rs232::Rs232Port& port) {
  while (auto frame = port.take_transmit()) {
    protocol::Rs232Deframer d(8192);
    auto events = d.feed(*frame);
    check(events.size() == 1 && events[0]);
    check(static_cast<bool>(rs232::decode_answer(events[0].value())));
  }
}

// One RS4 booted once (boot and the first scans dominate otherwise); every input starts
// from a copy of it, so runs stay independent.
const adapter::Adapter& booted() {
  static const adapter::Adapter rs4 = [] {
    adapter::AdapterConfig config;
    config.scanner.boot_duration = 80ms;
    adapter::Adapter a(config);
    // A 7-value window keeps the 0x23 stream from dominating each run (the full contour
    // is the codec fuzzer's and the benchmark's); 0x20 in the input may change it.
    auto set = scanner::factory_default();
    set.measurement = scanner::MeasurementOutput{1, 264, 270};
    if (!a.scanner().set_parameters(set, kStart)) __builtin_trap();
    a.power_on(kStart);
    a.on_time(kStart + 100ms);
    return a;
  }();
  return rs4;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  adapter::Adapter rs4 = booted();
  rs232::Rs232Port port(rs4);
  auto now = kStart + 100ms;
  port.attach(now);
  port.on_time(now);
  check_frames(port);
  std::span<const std::uint8_t> in(data, size);
  while (!in.empty()) {
    const std::uint8_t head = in[0];
    in = in.subspan(1);
    const std::size_t n = std::min<std::size_t>(head & 0x3FU, in.size());
    port.on_bytes(in.first(n), now);
    in = in.subspan(n);
    check_frames(port);
    static constexpr std::chrono::milliseconds kSteps[] = {0ms, 1ms, 10ms, 40ms};
    now += kSteps[head >> 6];
    port.on_time(now);
    check_frames(port);
    check(rs4.rs232_switched_through() == port.reachable());
  }
  check(!scanner::validate(rs4.scanner().parameters()));
  port.detach(now);
  check(!rs4.rs232_switched_through());
  return 0;
}
