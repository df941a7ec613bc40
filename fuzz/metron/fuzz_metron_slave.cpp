// libFuzzer target: the METRON in slave line mode (metron::MetronDevice with its receiver and
// command handler) driven by a fuzzed script of byte chunks, parity errors, time steps and
// scene changes. The first byte picks no-node or node 5. Invariants: no crash or hang;
// every frame the device sends is a well-formed reply [METRON manual "No node", "With
// node"] (start, node 5 in node mode, Length = bytes that follow - 1, valid checksum), and
// never more replies than delimited messages.
//
// Script: op byte, then its arguments
//   0 t      advance t ms (0..255)         3 b     set beam b interrupted, 4 b: free
//   1 n ...  n bytes to the device         5       toggle synchronism
//   2 b      byte b with a parity error    6       toggle the input
#include "metron/checksum.h"
#include "metron/metron_device.h"
#include "stream/clock.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>

namespace {

using namespace rs4sim;
using namespace std::chrono_literals;

void check_frame(const std::vector<std::uint8_t>& f, const metron::Options& o) {
  const std::size_t header = o.node_enabled ? 3 : 2;
  if (f.size() < header + 2 || f[0] != o.wire.frame_start) std::abort();
  if (o.node_enabled && f[1] != o.node) std::abort();
  if (f[header - 1] != f.size() - header - 1) std::abort();
  const auto body = std::span<const std::uint8_t>(f).subspan(header, f.size() - header - 1);
  if (metron::checksum(body, o.checksum_reading) != f.back()) std::abort();
}

struct Harness {
  metron::Options options;
  stream::ManualClock clock;
  std::optional<metron::MetronDevice> device;
  std::uint64_t replies = 0;

  void drain() {
    while (auto f = device->take_transmit()) {
      check_frame(*f, options);
      ++replies;
    }
  }
  void advance(stream::Duration d) {
    const auto target = clock.now() + d;
    for (int guard = 0; guard < 10000; ++guard) {
      const auto dl = device->next_deadline();
      if (!dl || *dl > target) break;
      if (*dl > clock.now()) clock.set(*dl);
      device->on_time(clock.now());
      drain();
    }
    clock.set(target);
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  Harness h;
  h.options.node_enabled = (data[0] & 1U) != 0;
  h.options.node = 5;
  h.options.checksum_reading = (data[0] & 2U) != 0 ? metron::ChecksumReading::kEndAroundCarry
                                                   : metron::ChecksumReading::kModulo256;
  h.device.emplace(h.options);
  h.advance(0ms);
  const std::uint8_t* p = data + 1;
  const std::uint8_t* end = data + size;
  const auto arg = [&]() -> std::uint8_t { return p < end ? *p++ : 0; };
  while (p < end) {
    const std::uint8_t op = *p++;
    switch (op % 7) {
      case 0: h.advance(std::chrono::milliseconds(arg())); break;
      case 1: {
        const std::size_t n = std::min<std::size_t>(arg(), static_cast<std::size_t>(end - p));
        h.device->on_bytes(std::span<const std::uint8_t>(p, n), h.clock.now());
        p += n;
        break;
      }
      case 2: h.device->on_byte_with_parity_error(arg(), h.clock.now()); break;
      case 3: h.device->set_beam(arg(), true); break;
      case 4: h.device->set_beam(arg(), false); break;
      case 5: h.device->set_synchronised(!h.device->scene().synchronised()); break;
      case 6: h.device->set_input(!h.device->scene().input_high()); break;
    }
    h.drain();
  }
  h.advance(1s);
  if (h.replies > h.device->counters().messages) std::abort();
  return 0;
}
