// The GridScan demo of `rs4sim demo --device gridscan` (app/demos/demos.h): the curtain alone
// on the simulated line (stream::MemoryLine, 115200 8N1 with every frame's wire time) and the
// demo as its door controller: the power-up messages, the communication test of
// [GridScan manual §10.3] step by step (each answer compared with the manual's bytes), and a
// power cycle that runs the power-up again. Exits 0 when every step did what the manual says.
#include "app/demos/demos.h"
#include "app/demos/line_demo.h"
#include "app/runtime/run_options.h"
#include "gridscan/device.h"

#include <ostream>
#include <string>
#include <vector>

namespace rs4sim::app {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;

const Bytes kSync{0x43, 0x45, 0x44, 0x45};
Bytes with_sync(std::initializer_list<std::uint8_t> rest) {
  Bytes b = kSync;
  b.insert(b.end(), rest);
  return b;
}

class Demo : public LineDemo<gridscan::Device> {
 public:
  using LineDemo::LineDemo;
  int run() {
    n_.print(
        "GridScan/Pro SI, RC: 22 elements, blanking, door open; 115200 8N1 "
        "[GridScan manual §9.1]\n");
    return run_story(
        n_, {[this] { return power_up("power-up"); }, [this] { return communication_test(); },
             [this] { return power_cycle(); }});
  }

 private:
  // Waits for the next frame from the curtain and checks it against the manual's bytes.
  bool expect(const Bytes& want, dp::Duration limit, const std::string& what) {
    if (!run_([this] { return !arrived_.empty(); }, limit)) {
      return n_.check(false, "no frame from the curtain: expected " + what);
    }
    const Bytes frame = arrived_.front().bytes;
    arrived_.erase(arrived_.begin());
    n_.say("curtain -> " + hex(frame) + "  " + what);
    return n_.check(frame == want, what + ": the manual prints " + hex(want));
  }
  bool power_up(const std::string& why) {
    n_.print("\n== " + why + " [GridScan manual §10.1.1]\n");
    if (started_) {
      device_.power_on(clock_.now());
    } else {
      started_ = true;
      line_.start();
    }
    return expect(with_sync({0x00, 0xA0, 0x30, 0x31, 0x2E, 0x30, 0x32, 0x30, 0x33, 0x2E, 0x30, 0x34,
                             0x33, 0x7F, 0x67, 0x4B}),
                  10ms, "Info: Get version (SeqCnt 0): SW 01.02, HW 03.04") &&
           expect(with_sync({0x01, 0xB0, 0x16, 0x00, 0x69, 0x78, 0x27, 0x24}), 2s,
                  "Data: Reduced state (SeqCnt 1): door 22 = open, nothing interrupted; ready");
  }
  bool communication_test() {
    n_.print("\n== the communication test 0x23, as [GridScan manual §10.3] prints it\n");
    struct Step {
      Bytes request, answer;
      const char* what;
    };
    const std::vector<Step> steps{
        {{0, 0, 0, 0, 0x00, 0x23, 0, 0, 0, 0},
         with_sync({0x01, 0xA3, 0x07, 0xEF, 0x30, 0x3F, 0x78}),
         "error bits 07: CRC, SeqCnt, sync"},
        {{0, 0, 0, 0, 0x02, 0x23, 0, 0, 0, 0},
         with_sync({0x03, 0xA3, 0x05, 0x8F, 0x52, 0x0C, 0x72}),
         "error bits 05: CRC, sync"},
        {with_sync({0x04, 0x23, 0, 0, 0, 0}), with_sync({0x05, 0xA3, 0x01, 0x41, 0xCF, 0xDB, 0x65}),
         "error bits 01: CRC"},
        {with_sync({0x06, 0x23, 0xE2, 0x4B, 0x01, 0x70}),
         with_sync({0x07, 0xA3, 0x00, 0xF8, 0x8B, 0xAB, 0x62}), "error bits 00: all correct"},
    };
    for (const auto& s : steps) {
      n_.say("control -> " + hex(s.request));
      line_.write(s.request);
      if (!expect(s.answer, 100ms, std::string(s.what) + " (answered at the cycle end)"))
        return false;
    }
    return true;
  }
  bool power_cycle() {
    n_.print("\n== mains off for 500 ms\n");
    device_.power_off();
    n_.run_for(500ms);
    return n_.check(arrived_.empty(), "nothing sent while off") &&
           power_up("mains on again: the power-up runs again, SeqCnt from 0");
  }

  bool started_ = false;
};

}  // namespace

int run_gridscan_demo(RunSession& session, std::ostream& out, const DemoOptions& options) {
  return run_line_demo<Demo>(session, out, options, gridscan::Options{});
}

}  // namespace rs4sim::app
