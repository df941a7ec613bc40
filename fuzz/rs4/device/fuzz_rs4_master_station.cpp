// libFuzzer target: the master side of an RS4 segment (rs4::device::Rs4MasterStation) with a
// real Rs4Device at 4 on the memory bus, driven by a fuzzed script: raw frames to the master
// (its decoder and reply handling must drop garbage), record writes/reads, output bytes,
// Proxy-Enable, power cycles of the RS4 and time steps; and the Slave_Diag decoder
// f_diagnosis_number() on the raw input. Invariants: no crash or hang; the unwrapped input
// byte is 0 whenever the F-host is passivated; every RecordResult answers a request made.
//
// Script: op byte, then its arguments
//   0 t      advance t+1 ms          3 b      process output byte b
//   1 n ...  raw frame (n bytes) to the master
//   2 n ...  record write of n bytes (1..240), then a record read
//   4        power cycle of the RS4  5 b      Proxy-Enable = b & 1
#include "dp/link/memory_bus.h"
#include "rs4/device/rs4_device.h"
#include "rs4/device/rs4_master_station.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

namespace {

using namespace std::chrono_literals;
namespace device = rs4sim::rs4::device;

constexpr std::uint8_t kRs4 = 4;

struct Harness {
  Harness() : station(config()), bus(clock), rs4(device_config()) {
    bus.attach(station);
    bus.attach(rs4);
    bus.start();
    rs4.power_on(clock.now());
  }
  static device::Rs4MasterStationConfig config() {
    device::Rs4MasterStationConfig c;
    c.slaves.push_back(device::Rs4MasterOptions{});
    c.auto_ack_rei = true;
    return c;
  }
  static device::Rs4DeviceConfig device_config() {
    device::Rs4DeviceConfig c;
    c.boot_time = 200ms;
    c.adapter_init = 100ms;
    return c;
  }
  void run_for(rs4sim::dp::Duration d) {
    bus.run_for(d);
    station.take_events(events);
    for (const auto& e : events) {
      const auto* r = std::get_if<device::RecordResult>(&e);
      if (r != nullptr && (r->id == 0 || r->id > last_id)) std::abort();
    }
    events.clear();
    if (station.fhost(kRs4)->passivated() && station.input_byte(kRs4) != 0) std::abort();
  }

  rs4sim::dp::ManualClock clock;
  device::Rs4MasterStation station;
  rs4sim::dp::link::MemoryBus bus;
  device::Rs4Device rs4;
  std::vector<device::Rs4MasterEvent> events;
  rs4sim::dp::master::Dpv1RequestId last_id = 0;
};

void step(Harness& h, std::uint8_t op, const std::uint8_t*& p, const std::uint8_t* end) {
  const auto arg = [&]() -> std::uint8_t { return p < end ? *p++ : 0; };
  switch (op % 6) {
    case 0: h.run_for(std::chrono::milliseconds(arg() + 1)); break;
    case 1: {
      const std::size_t n = std::min<std::size_t>(arg(), static_cast<std::size_t>(end - p));
      h.bus.send_raw(h.station.address(), std::span<const std::uint8_t>(p, n));
      p += n;
      h.run_for(5ms);
      break;
    }
    case 2: {
      const std::size_t n = std::min<std::size_t>(arg(), static_cast<std::size_t>(end - p));
      if (n > 0 && n <= 240) {
        if (auto id = h.station.write_record(kRs4, std::span<const std::uint8_t>(p, n))) {
          h.last_id = id.value();
        }
        if (auto id = h.station.read_record(kRs4)) h.last_id = id.value();
      }
      p += n;
      h.run_for(50ms);
      break;
    }
    case 3: (void)h.station.set_output_byte(kRs4, arg()); break;
    case 4:
      h.rs4.power_off(h.clock.now());
      h.run_for(10ms);
      h.rs4.power_on(h.clock.now());
      break;
    default: (void)h.station.set_proxy_enable(kRs4, (arg() & 1) != 0); break;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 512) return 0;  // keeps one input well under a millisecond of real time
  (void)device::f_diagnosis_number(std::span<const std::uint8_t>(data, size));
  Harness h;
  h.run_for(400ms);  // data exchange, RS4 up
  const std::uint8_t* p = data;
  const std::uint8_t* end = data + size;
  for (int steps = 0; p < end && steps < 64; ++steps) {
    const std::uint8_t op = *p++;
    step(h, op, p, end);
  }
  return 0;
}
