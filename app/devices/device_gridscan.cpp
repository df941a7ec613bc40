// Device entry `gridscan`: the virtual CEDES GridScan/Pro SI with RS485 interface, type
// suffix RC (gridscan/device.h, docs/gridscan.md), on pty, serial or UDP at the fixed
// 115200 8N1 ([GridScan manual §9.1]). The options fill a gridscan::Options; its validate()
// has the last word.
//
//   rs4sim run --device gridscan --link pty --elements 22 --mode blanking --door 10 --blocked 3
//   rs4sim run --device gridscan --link memory --grpc 127.0.0.1:50051   (the simulated clock:
//              SimTime, GridScan.Exchange/Receive/PowerCycle, docs/gridscan.md)
//   --mode blanking|static[,cycle=<ms>]: the delivery mode and t_CYCLE (gridscan/mode_spec.h)
#include "app/devices/device_options.h"
#include "app/devices/device_registry.h"
#include "app/devices/line_segment.h"
#include "app/runtime/usage_error.h"
#include "gridscan/description.h"
#include "gridscan/device.h"
#include "gridscan/mode_spec.h"

#include <chrono>
#include <ostream>

namespace rs4sim::app {
namespace {

// The curtain's address in the API: 0, there is no bus address (the RS485 link is
// point-to-point, [GridScan manual §9]).
constexpr std::uint8_t kAddress = 0;

gridscan::Options gridscan_options(const DeviceOptions& o) {
  gridscan::Options g;
  if (o.elements) {
    if (*o.elements < 12 || *o.elements > 60) {
      throw UsageError("--elements " + std::to_string(*o.elements) +
                       ": a GridScan edge has 12..60");
    }
    g.elements = static_cast<unsigned>(*o.elements);
  }
  if (!o.mode.empty()) {
    if (const auto why = gridscan::apply_mode_spec(o.mode, g); !why.empty()) {
      throw UsageError("--mode " + o.mode + ": " + why);
    }
  }
  if (o.door) {
    if (*o.door < 0 || *o.door > static_cast<int>(g.elements)) {
      throw UsageError("--door " + std::to_string(*o.door) + ": the door position is 0.." +
                       std::to_string(g.elements) + " (elements below the door edge)");
    }
    g.door_position = static_cast<unsigned>(*o.door);
  }
  check_blocked(o, static_cast<int>(g.elements), "elements");
  if (o.blocked) {
    for (const int e : *o.blocked) g.blocked |= std::uint64_t{1} << static_cast<unsigned>(e - 1);
  }
  if (const auto why = g.validate(); !why.empty()) throw UsageError("gridscan: " + why);
  return g;
}

// The status line at the end of a run.
void print_line_status(std::ostream& out, const gridscan::Device& d,
                       const stream::ByteCounters& c) {
  print_line_summary(out, gridscan::description(), d.counters(), "", c);
}

// The curtain on its line: alone on the simulated line with --link memory (docs/gridscan.md
// "Simulated clock"), else on pty, serial or UDP (LineInstance).
const LineDevice<gridscan::Device> kGridScanLine{
    .kind = gridscan::description().kind,
    .protocol = gridscan::description().link,
    .address = [](const gridscan::Device&) { return kAddress; },
    .print_status = print_line_status,
};

class GridScanInstance final : public LineInstance<gridscan::Device> {
 public:
  explicit GridScanInstance(const DeviceOptions& o)
      : GridScanInstance(gridscan_options(o), o.mains != "off") {}
  GridScanInstance(const gridscan::Options& o, bool mains_on)
      : LineInstance(kGridScanLine, o), options_(o), mains_on_(mains_on) {}
  // --mains off: the curtain stays dark until SIGUSR1 or GridScan.SetPower, so a controller
  // that opens the line late (or flushes it on open) still sees the power-up messages.
  void start(dp::TimePoint now) override {
    if (mains_on_)
      device_.power_on(now);
    else
      device_.power_off();
  }
  // SIGUSR1: a power cycle (the power-up messages, the configuration window and the alignment
  // arming again, e.g. once the controller has opened the line); SIGUSR2: mains off.
  void on_user_signal(bool second, dp::TimePoint now) override {
    device_.power_off();
    if (!second) device_.power_on(now);
  }
  [[nodiscard]] std::string describe() const override {
    const auto cycle_us =
        std::chrono::duration_cast<std::chrono::microseconds>(options_.cycle_time()).count();
    return "GridScan/Pro SI, RC (" + std::to_string(options_.elements) + " elements, " +
           std::string(gridscan::to_token(device_.configuration())) + " mode, " +
           stream::to_string(device_.line_settings()) + ", t_CYCLE " +
           std::to_string(cycle_us / 1000) + "." + std::to_string(cycle_us % 1000 / 100) + " ms; " +
           (mains_on_ ? "" : "mains off until SIGUSR1; ") +
           "SIGUSR1 power-cycles it, SIGUSR2 switches it off)";
  }

 private:
  gridscan::Options options_;
  bool mains_on_;
};

}  // namespace

DeviceEntry gridscan_device_entry() {
  auto entry = line_device_entry<GridScanInstance>(gridscan::description(), kGridScanLine,
                                                   gridscan_options, run_gridscan_demo);
  entry.simulate = [](const DeviceOptions& o) {
    auto segment =
        std::make_unique<LineSegment<gridscan::Device>>(kGridScanLine, gridscan_options(o));
    // --mains off: dark until GridScan.SetPower / PowerCycle (the device powers up at the
    // line's first call unless power_off() came first).
    if (o.mains == "off") segment->device().power_off();
    return segment;
  };
  return entry;
}

}  // namespace rs4sim::app
