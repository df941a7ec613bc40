// The METRON demo of `rs4sim demo --device metron` (app/demos/demos.h): the Receiver alone in
// slave line mode on the simulated line (stream::MemoryLine, 19200 8E1 with every frame's
// wire time) and the demo as its host: the OSSD status of a free curtain answered after
// exactly Equation 3's delay, an object and its measurements, the error answers E1..E5 of
// the manual's "ERROR HANDLING", and a parity error that costs the whole message its reply
// [METRON manual "Slave line mode"]. The byte values are the project's EXTENSION
// (metron/wire_table.h): the manual's figures of them were lost. Exits 0 when every step did
// what the manual says.
#include "app/demos/demos.h"
#include "app/demos/line_demo.h"
#include "app/runtime/run_options.h"
#include "metron/device.h"

#include <ostream>
#include <string>
#include <vector>

namespace rs4sim::app {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;

// #12 Request OSSD status: start, length 1, command, checksum (~ of command and data).
const Bytes kOssdStatus{0x02, 0x01, 0x0C, 0xF3};

class Demo : public LineDemo<metron::Device> {
 public:
  using LineDemo::LineDemo;
  int run() {
    n_.print(
        "METRON Receiver, 24 beams, slave line mode without node, 19200 8E1, scan cycle "
        "10 ms, t_response 20 ms [METRON manual \"Serial line management\"]\n"
        "(byte values: the project's EXTENSION table, docs/metron.md)\n");
    line_.start();
    return run_story(n_, {[this] { return free_curtain(); }, [this] { return an_object(); },
                          [this] { return error_answers(); }, [this] { return parity_error(); }});
  }

 private:
  // Sends `request`, waits for one reply (none within 100 ms: nullptr).
  const stream::LineFrame* ask(const Bytes& request, const std::string& what) {
    n_.say("host -> " + hex(request) + "  " + what);
    arrived_.clear();
    sent_ = clock_.now();
    line_.write(request, stream::Pacing::kPerCharacter);
    if (!run_([this] { return !arrived_.empty(); }, 100ms)) return nullptr;
    n_.say("receiver -> " + hex(arrived_.front().bytes));
    return &arrived_.front();
  }
  bool expect(const Bytes& request, const Bytes& reply, const std::string& what) {
    const auto* got = ask(request, what);
    return n_.check(got != nullptr && got->bytes == reply, what + ": expected " + hex(reply));
  }
  bool free_curtain() {
    n_.print("\n== a free curtain: #12 Request OSSD status\n");
    const auto* got = ask(kOssdStatus, "#12 Request OSSD status");
    if (!n_.check(got != nullptr && got->bytes == Bytes{0x02, 0x03, 0x0C, 0x01, 0x01, 0xF1},
                  "OSSD1 and OSSD2 ON")) {
      return false;
    }
    // Equation 3: t_late = n_byte x 11 bit x 52.08 us + t_response / 2 from the request's
    // first byte (docs/metron.md): 4 bytes = 44 bits at 19200 = 2.291667 ms, + 10 ms. The
    // first byte is the Receiver's once its 11 bits have arrived, 572.917 us after they began.
    const auto first_byte = sent_ + std::chrono::nanoseconds(572'917);
    const auto late = got->start - first_byte;
    n_.say("the reply began " +
           std::to_string(std::chrono::duration_cast<std::chrono::microseconds>(late).count()) +
           " us after the Receiver had the request's first byte");
    return n_.check(late >= 12'291'666ns && late <= 12'291'668ns,
                    "the reply starts 12.292 ms after the first byte (Equation 3)");
  }
  bool an_object() {
    n_.print("\n== an object on beams 9-13\n");
    const std::vector<std::uint16_t> beams{9, 10, 11, 12, 13};
    device_.set_interrupted(beams);
    n_.say("scene: beams 9-13 interrupted");
    return expect(kOssdStatus, {0x02, 0x03, 0x0C, 0x00, 0x00, 0xF3}, "#12: both OSSDs OFF") &&
           expect({0x02, 0x04, 0x0A, 0x01, 0x02, 0x03, 0xEF},
                  {0x02, 0x04, 0x0A, 0x09, 0x0D, 0x05, 0xDA},
                  "#10 measurements first, last, count: 9, 13, 5");
  }
  bool error_answers() {
    n_.print("\n== the error answers of \"ERROR HANDLING\" [METRON manual \"Slave line mode\"]\n");
    if (!(expect({0x02, 0x01, 0x0C, 0xF4}, {0x02, 0x01, 0xE1, 0x1E}, "E1: a wrong checksum") &&
          expect({0x02, 0x02, 0x0C, 0x00, 0xF3}, {0x02, 0x01, 0xE2, 0x1D},
                 "E2: #12 with a data byte (wrong length)") &&
          expect({0x02, 0x01, 0x06, 0xF9}, {0x02, 0x01, 0xE3, 0x1C},
                 "E3: Stop OSSD measurement without a start") &&
          expect({0x02, 0x01, 0x08, 0xF7}, {0x02, 0x01, 0xE5, 0x1A},
                 "E5: Stop measurement without a start"))) {
      return false;
    }
    device_.set_synchronised(false);
    n_.say("scene: the emitter's synchronism is lost");
    const bool e4 = expect({0x02, 0x02, 0x07, 0x01, 0xF7}, {0x02, 0x01, 0xE4, 0x1B},
                           "E4: Start measurement without synchronism");
    device_.set_synchronised(true);
    return e4;
  }
  bool parity_error() {
    n_.print(
        "\n== a parity error in the middle of a message: the whole message is rejected, no "
        "reply\n");
    n_.say("host -> 02 01 [0C with a parity error] F3");
    arrived_.clear();
    line_.write(Bytes{0x02, 0x01}, stream::Pacing::kPerCharacter);
    line_.write_damaged(0x0C);
    line_.write(Bytes{0xF3}, stream::Pacing::kPerCharacter);
    const bool silent = !run_([this] { return !arrived_.empty(); }, 100ms);
    return n_.check(silent, "no reply within 100 ms") &&
           expect(kOssdStatus, {0x02, 0x03, 0x0C, 0x00, 0x00, 0xF3},
                  "the next message is answered again");
  }

  stream::TimePoint sent_{};
};

}  // namespace

int run_metron_demo(RunSession& session, std::ostream& out, const DemoOptions& options) {
  return run_line_demo<Demo>(session, out, options, metron::Options{});
}

}  // namespace rs4sim::app
