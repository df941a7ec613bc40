// libFuzzer target: a whole RS4 segment (GSD master + F-host + Rs4Device on the memory bus)
// driven by a fuzzed script of bus frames, DPV1 records, process outputs, power and scene
// actions and time steps. Invariants: no crash or hang; one cycle after any step the OSSD
// bit of the device is 1 only while the scanner's OSSDs are on ([RS4 manual §5.1.1]: the
// only safety bit); the F-host's input is 0 whenever it is passivated; a powered-off or link-down
// station sends nothing.
//
// Script: op byte, then its arguments
//   0 t      advance t+1 ms          3 b      process output byte b
//   1 n ...  raw frame (n bytes) to the RS4 (its decoder must drop garbage)
//   2 n ...  DPV1 WRITE slot 0 index 2 with n bytes (when in data exchange), then a READ
//   4        power cycle             5 d      object at d·20 mm straight ahead
//   6 f      inject fault f % 4      7 f      clear fault f % 4 and a restart pulse
#include "rs4/device/rs4_segment.h"
#include "rs4/scanner/faults.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace {

using namespace std::chrono_literals;
using rs4sim::rs4::device::Rs4Segment;

// Harness actions act on the scanner at once; the adapter composes its input byte on its
// next call (a bus cycle or a scanner deadline) and shows the RS4 10 ms later ("Reaktionszeit
// PROFIsafe-Adapter 10 ms", [RS4 manual, technical data]). The invariant is checked after 25 ms,
// more than one 10 ms master cycle plus that 10 ms; an OSSD bit of 1 over switched-off OSSDs
// then gets the adapter's 10 ms more (the scanner may have switched off on its own late in
// the window): the OSSD bit never outlives the scanner's OSSDs by more than that.
void check(Rs4Segment& s) {
  s.run_for(25ms);
  auto& d = s.device();
  if (d.adapter().ossd_bit() && !d.scanner().ossd()) s.run_for(10ms);
  const auto fail = [](const char* what) {
    std::fprintf(stderr, "invariant: %s\n", what);
    std::abort();
  };
  if (d.adapter().ossd_bit() && !d.scanner().ossd()) fail("OSSD bit 1, the RS4's OSSDs off");
  if (s.fhost().passivated() && s.input_byte() != 0) fail("passivated input not 0");
  if (!d.powered() && d.take_transmit().has_value()) fail("powered off and sending");
}

void step(Rs4Segment& s, std::uint8_t op, const std::uint8_t*& p, const std::uint8_t* end) {
  const auto arg = [&]() -> std::uint8_t { return p < end ? *p++ : 0; };
  switch (op % 8) {
    case 0: s.run_for(std::chrono::milliseconds(arg() + 1)); break;
    case 1: {
      const std::size_t n = std::min<std::size_t>(arg(), static_cast<std::size_t>(end - p));
      s.bus().send_raw(s.rs4_address(), std::span<const std::uint8_t>(p, n));
      p += n;
      s.run_for(5ms);
      break;
    }
    case 2: {
      const std::size_t n = std::min<std::size_t>(arg(), static_cast<std::size_t>(end - p));
      if (n > 0 && n <= 240 && s.in_data_exchange()) {
        (void)s.write_record(std::span<const std::uint8_t>(p, n), 300ms);
        (void)s.read_record(240, 300ms);
      }
      p += n;
      break;
    }
    case 3: s.set_output_byte(arg()); break;
    case 4:
      s.power_off();
      s.run_for(10ms);
      s.power_on();
      break;
    case 5:
      (void)s.device().scanner().edit_scene(s.now()).add(
          rs4sim::rs4::scanner::Circle{{0, arg() * 20.0}, 50});
      break;
    case 6:
      (void)s.device().scanner().inject_fault(static_cast<rs4sim::rs4::scanner::Fault>(arg() % 4),
                                              s.now());
      break;
    default:
      (void)s.device().scanner().clear_fault(static_cast<rs4sim::rs4::scanner::Fault>(arg() % 4),
                                             s.now());
      s.set_output_byte(static_cast<std::uint8_t>(s.output_byte() | 0x80));
      s.run_for(200ms);
      s.set_output_byte(static_cast<std::uint8_t>(s.output_byte() & 0x7F));
      break;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 512) return 0;  // keeps one input well under a millisecond of real time
  rs4sim::rs4::device::Rs4SegmentConfig c;
  c.device.boot_time = 200ms;
  c.device.adapter_init = 100ms;
  c.auto_ack_rei = true;
  Rs4Segment s(c);
  s.power_on();
  s.run_for(400ms);  // data exchange, RS4 up
  const std::uint8_t* p = data;
  const std::uint8_t* end = data + size;
  for (int steps = 0; p < end && steps < 64; ++steps) {
    const std::uint8_t op = *p++;
    step(s, op, p, end);
    check(s);
  }
  return 0;
}
