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

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  adapter::AdapterConfig config;
  config.scanner.boot_duration = 80ms;
  adapter::Adapter rs4(config);
  rs232::Rs232Port port(rs4);
  auto now = rs4sim::stream::TimePoint{std::chrono::hours(1)};
  rs4.power_on(now);
  port.attach(now);
  now += 100ms;
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
    static constexpr std::chrono::milliseconds kSteps[] = {0ms, 1ms, 40ms, 130ms};
    now += kSteps[head >> 6];
    port.on_time(now);
    check_frames(port);
    check(!scanner::validate(rs4.scanner().parameters()));
    check(rs4.rs232_switched_through() == port.reachable());
  }
  port.detach(now);
  check(!rs4.rs232_switched_through());
  return 0;
}
