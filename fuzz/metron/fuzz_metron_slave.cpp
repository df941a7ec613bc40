// libFuzzer target: the METRON in slave line mode (metron::Device with its receiver and
// command handler) driven by a fuzzed script of byte chunks, parity errors, time steps and
// scene changes. The first byte picks no-node or node 5. Invariants: no crash or hang;
// every frame the device sends is a well-formed reply [METRON manual "No node", "With
// node"] (start, node 5 in node mode, Length = bytes that follow - 1, valid checksum), and
// never more replies than delimited messages.
//
// Script: op byte, then its arguments
//   0 t      advance t ms (0..255)         3 b     set beam b interrupted, 4 b: free
//   1 n ...  n bytes to the device         5 x     toggle synchronism
//   2 b      byte b with a parity error    6 x     toggle the input (x ignored)
//            (it arrives one character time after now, or after the damaged
//            characters before it, in line order)
#include "fuzz/metron/metron_script.h"
#include "metron/checksum.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>

namespace {

using namespace rs4sim;

void check_frame(std::span<const std::uint8_t> f, const metron::Options& o) {
  const std::size_t header = o.node_enabled ? 3 : 2;
  if (f.size() < header + 2 || f[0] != o.wire.frame_start) std::abort();
  if (o.node_enabled && f[1] != o.node) std::abort();
  if (f[header - 1] != f.size() - header - 1) std::abort();
  const auto body = f.subspan(header, f.size() - header - 1);
  if (metron::checksum(body, o.checksum_reading) != f.back()) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  metron::Options o;
  o.node_enabled = (data[0] & 1U) != 0;
  o.node = 5;
  o.checksum_reading = (data[0] & 2U) != 0 ? metron::ChecksumReading::kEndAroundCarry
                                           : metron::ChecksumReading::kModulo256;
  std::uint64_t replies = 0;
  metron::fuzzing::Rig rig(metron::fuzzing::sent_to([&](std::span<const std::uint8_t> f,
                                                        stream::TimePoint) {
                             check_frame(f, o);
                             ++replies;
                           }),
                           o);
  auto& d = rig.device();
  const std::uint8_t* p = data + 1;
  const std::uint8_t* end = data + size;
  while (p < end) {
    const auto op = static_cast<std::uint8_t>(*p++ % 7);
    if (metron::fuzzing::common_op(rig, op, p, end)) continue;
    const std::uint8_t arg = p < end ? *p++ : 0;
    switch (op) {
      case 2: rig.write_damaged(arg); break;  // one character time from now
      case 3: d.set_beam(arg, true); break;
      case 4: d.set_beam(arg, false); break;
      case 5: d.set_synchronised(!d.scene().synchronised()); break;
      default: d.set_input(!d.scene().input_high()); break;
    }
  }
  rig.run_for(std::chrono::seconds(1));
  if (replies > d.counters().messages) std::abort();
  return 0;
}
