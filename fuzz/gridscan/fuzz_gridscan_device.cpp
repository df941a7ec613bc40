// libFuzzer target: the GridScan device ([GridScan manual §10, §11]) driven by a fuzzed
// script of byte chunks, time steps, scene changes and faults on the manual clock.
// Invariants: no crash or hang; every frame it sends is 10..20 bytes with the sync
// pattern, a known response ID and a correct CRC (no fault injected), a payload of the
// ID's length; the powered-off device sends nothing.
//
// Script: op byte, then its arguments
//   0 t      advance t·100 µs          1 n ...  n bytes arrive now
//   2 r      a valid request for ID r with the expected SeqCnt (reaches the commands)
//   3 d      door position d           4 m      blocked elements = m spread over 60 bits
//   5        power cycle               6 f      internal failure / soiling from f
#include "gridscan/device.h"
#include "stream/testing/line_rig.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>

namespace {

using namespace std::chrono_literals;
using namespace rs4sim::gridscan;
using rs4sim::stream::FrameDirection;

// The device on the shared line rig; every frame is checked as the device gives it out (the
// line's tap), the power-up message at the line's start included.
struct Harness {
  explicit Harness(const Options& o)
      : elements(o.elements),
        rig([this](std::span<const std::uint8_t> f, rs4sim::stream::TimePoint, FrameDirection d) {
          if (d == FrameDirection::kSent) on_sent(f);
        },
            o) {
    device = &rig.device();
  }

  void on_sent(std::span<const std::uint8_t> f) {
    // (null while the rig starts: the device is powering up then)
    if (device != nullptr && device->power() == PowerState::kOff) std::abort();
    const auto decoded = decode_response(f, elements);
    if (!decoded) std::abort();
    const std::uint8_t seq = f[4];
    const std::uint8_t id = f[5];
    if (id == 0xA0 && seq == 0) next_seq = 2;  // power-up: A0 0, B0 1
    if (id == static_cast<std::uint8_t>(asked | kDirectionBit)) {
      next_seq = static_cast<std::uint8_t>(seq + 1);
    }
  }

  unsigned elements;
  std::uint8_t next_seq = 2;  // the SeqCnt the next request must carry
  std::uint8_t asked = 0;     // the ID of the last scripted request
  const Device* device = nullptr;
  rs4sim::stream::testing::LineRig<Device> rig;
};

void step(Harness& h, std::uint8_t op, const std::uint8_t*& p, const std::uint8_t* end) {
  const auto arg = [&]() -> std::uint8_t { return p < end ? *p++ : 0; };
  auto& device = h.rig.device();
  switch (op % 7) {
    case 0: h.rig.run_for(std::chrono::microseconds(100 * (arg() + 1))); break;
    case 1: {
      const std::size_t n = std::min<std::size_t>(arg(), static_cast<std::size_t>(end - p));
      h.rig.send(std::span<const std::uint8_t>(p, n));
      p += n;
      break;
    }
    case 2: {
      h.asked = static_cast<std::uint8_t>(arg() & kIdMask);
      h.rig.send(encode(Frame{h.next_seq, h.asked, {}}));
      h.rig.run_for(80ms);
      break;
    }
    case 3: device.set_door_position(arg()); break;
    case 4: device.set_blocked(std::uint64_t{arg()} * 0x0101010101010101ULL); break;
    case 5:  // both wake the line, which drains the device
      device.power_off();
      device.power_on(h.rig.now());
      break;
    default: {
      const std::uint8_t f = arg();
      device.set_internal_failure((f & 1) != 0);
      device.set_soiling(static_cast<std::uint8_t>(f >> 1));
      break;
    }
  }
  (void)h.rig.take();  // what reached the controller: checked as it was given out
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 512) return 0;
  Options o;
  o.ready_time = 5ms;
  o.config_window = 10s;
  if (size > 0) o.elements = kMinElements + data[0] % (kMaxElements - kMinElements + 1);
  Harness h(o);
  h.rig.run_for(10ms);  // ready
  const std::uint8_t* p = data + (size > 0 ? 1 : 0);
  const std::uint8_t* end = data + size;
  for (int steps = 0; p < end && steps < 64; ++steps) {
    const std::uint8_t op = *p++;
    step(h, op, p, end);
  }
  return 0;
}
