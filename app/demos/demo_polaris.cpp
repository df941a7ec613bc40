// The Polaris demo of `rs4sim demo --device polaris` (app/demos/demos.h): the barrier alone
// as a Modbus RTU slave on the simulated line (stream::MemoryLine, 19200 8N1 with every
// frame's wire time) and the demo as its Modbus master: an empty barrier, two objects in FL4
// with the hole between them confirmed by the PN2 filter [Polaris manual §3] (the request and
// answer of [Polaris manual §8.2.3] byte for byte), a request with a broken CRC answered by
// exception 07 and a broadcast nobody answers [Modbus serial line V1.02 §2.1]. Exits 0 when every
// step did what the manual says.
#include "app/demos/demos.h"
#include "app/demos/line_demo.h"
#include "app/runtime/run_options.h"
#include "polaris/device.h"

#include <ostream>
#include <string>
#include <vector>

namespace rs4sim::app {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;

std::vector<std::uint16_t> range(std::uint16_t first, std::uint16_t last) {
  std::vector<std::uint16_t> out;
  for (auto b = first; b <= last; ++b) out.push_back(b);
  return out;
}

// PL 10 with 40 beams, FL4, slave 1 (the barrier of [Polaris manual §8.2.3]); hole detection
// confirmed over 3 scans of 5 ms.
polaris::Options demo_options() {
  polaris::Options o;
  o.family = polaris::Family::kPl10;
  o.beams = 40;
  o.mode = polaris::DataMode::kFl4;
  o.address = 1;
  o.detection = polaris::Detection::kHole;
  o.pn2_filter = 3;
  o.response_time = 5ms;
  return o;
}

// FC 3, 10 registers from 0x2000 (the FL4 block), slave 1 [Polaris manual §8.2.3].
const Bytes kReadFl4{0x01, 0x03, 0x20, 0x00, 0x00, 0x0A, 0xCE, 0x0D};

class Demo : public LineDemo<polaris::Device> {
 public:
  using LineDemo::LineDemo;
  int run() {
    n_.print(
        "Polaris PL 10, 40 beams, FL4, Modbus RTU slave 1, 19200 8N1, hole detection "
        "over 3 scans [Polaris manual §7.4.2]\n");
    line_.start();
    return run_story(
        n_, {[this] { return empty_barrier(); }, [this] { return two_objects_and_a_hole(); },
             [this] { return crc_error(); }, [this] { return broadcast(); }});
  }

 private:
  // Sends `request` and waits for the barrier's answer (nullopt-like empty: none in 100 ms).
  Bytes ask(const Bytes& request, const std::string& what) {
    n_.say("master -> " + hex(request) + "  " + what);
    arrived_.clear();
    line_.write(request);
    if (!run_([this] { return !arrived_.empty(); }, 100ms)) return {};
    const Bytes reply = arrived_.front().bytes;
    n_.say("barrier -> " + hex(reply));
    return reply;
  }
  bool set(const std::vector<std::uint16_t>& beams, const std::string& what) {
    n_.say("scene: " + what);
    return n_.check(!device_.set_interrupted(beams, clock_.now()), "the scene is refused");
  }
  bool empty_barrier() {
    n_.print("\n== nothing in the light curtain\n");
    const Bytes reply = ask(kReadFl4, "FC 3: the FL4 block, 10 registers at 0x2000");
    // 10 zero words; CRC-16/MODBUS A3 67, worked out apart from the code
    Bytes empty{0x01, 0x03, 0x14};
    empty.resize(3 + 20, 0x00);
    empty.insert(empty.end(), {0xA3, 0x67});
    return n_.check(reply == empty,
                    "an empty barrier answers 10 zero words [Polaris manual §8.2.3]") &&
           n_.check(!device_.pn1() && !device_.pn2(clock_.now()), "PN1 and PN2 off");
  }
  bool two_objects_and_a_hole() {
    n_.print(
        "\n== two objects, beams 9-13 and 25-34 (the scene of [Polaris manual §8.2.3]), "
        "and the hole between them [Polaris manual §3]\n");
    auto beams = range(9, 13);
    const auto second = range(25, 34);
    beams.insert(beams.end(), second.begin(), second.end());
    if (!set(beams, "beams 9-13 and 25-34 interrupted")) return false;
    if (!n_.check(device_.pn1() && !device_.pn2(clock_.now()),
                  "PN1 on at once; PN2 off: the hole must last 3 scans")) {
      return false;
    }
    n_.run_for(14ms);
    if (!n_.check(!device_.pn2(clock_.now()), "PN2 still off after 14 ms")) return false;
    n_.run_for(1ms);
    n_.say("PN2 on: the hole was seen for 3 scans of 5 ms");
    if (!n_.check(device_.pn2(clock_.now()), "PN2 on after 15 ms")) return false;
    const Bytes reply = ask(kReadFl4, "FC 3: the FL4 block");
    const Bytes manual{0x01, 0x03, 0x14, 0x00, 0x09, 0x00, 0x0D, 0x00, 0x19, 0x00, 0x22, 0x00, 0x00,
                       0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x09, 0x00, 0x22, 0x19, 0x5A};
    n_.say("objects (9, 13) and (25, 34), none 3 and 4, overall (9, 34)");
    return n_.check(reply == manual, "the answer: the manual prints " + hex(manual));
  }
  bool crc_error() {
    n_.print("\n== a request whose CRC bytes are swapped [Polaris manual §8.1.2]\n");
    const Bytes reply =
        ask({0x01, 0x03, 0x20, 0x00, 0x00, 0x0A, 0x0D, 0xCE}, "CRC CE 0D sent as 0D CE");
    // The manual's 03 83 07 A1 32 for slave 3; for slave 1 the CRC is 00 F2 (worked out apart)
    return n_.check(reply == Bytes{0x01, 0x83, 0x07, 0x00, 0xF2},
                    "exception: function 03 | 0x80, code 07") &&
           n_.check(device_.counters().crc_errors == 1, "one CRC error counted");
  }
  bool broadcast() {
    n_.print("\n== a broadcast (slave 0) is never answered [Modbus serial line V1.02 §2.1]\n");
    const Bytes reply = ask({0x00, 0x03, 0x20, 0x00, 0x00, 0x02, 0xCE, 0x1A}, "FC 3 to slave 0");
    return n_.check(reply.empty(), "no answer within 100 ms");
  }
};

}  // namespace

int run_polaris_demo(RunSession& session, std::ostream& out, const DemoOptions& options) {
  return run_line_demo<Demo>(session, out, options, demo_options());
}

}  // namespace rs4sim::app
