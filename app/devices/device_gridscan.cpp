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
#include "gridscan/device.h"
#include "gridscan/mode_spec.h"
#include "rpc/device_target.h"
#include "rpc/gridscan_service.h"
#include "rpc/rs4_services.h"

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
  const auto& k = d.counters();
  out << "gridscan: frames " << k.frames << ", answered " << k.answered << " (communication tests "
      << k.comm_tests << "), streamed " << k.streamed << ", dropped " << k.dropped()
      << " (truncated " << k.truncated << ", oversized " << k.oversized << ", sync " << k.bad_sync
      << ", CRC " << k.bad_crc << ", SeqCnt " << k.bad_seq << ", ID " << k.unknown_id
      << ", direction " << k.direction_bit << ", busy " << k.busy << ", not ready " << k.not_ready
      << "), restarts " << k.restarts << ", bytes received " << c.bytes_received << ", sent "
      << c.bytes_sent << ", link errors " << c.link_errors << std::endl;
}

class GridScanInstance final : public DeviceInstance {
 public:
  GridScanInstance(const gridscan::Options& o, bool mains_on)
      : options_(o), device_(o), mains_on_(mains_on) {}
  std::vector<stream::ByteDevice*> byte_devices() override { return {&tap_}; }
  [[nodiscard]] stream::LineProtocol line_protocol() const override {
    return stream::LineProtocol::kGridScan;
  }
  // --mains off: the curtain stays dark until SIGUSR1 or GridScan.SetPower, so a controller
  // that opens the line late (or flushes it on open) still sees the power-up messages.
  void start(dp::TimePoint now) override {
    if (mains_on_) device_.power_on(now);
    else device_.power_off();
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
           std::to_string(cycle_us / 1000) + "." + std::to_string(cycle_us % 1000 / 100) +
           " ms; " + (mains_on_ ? "" : "mains off until SIGUSR1; ") +
           "SIGUSR1 power-cycles it, SIGUSR2 switches it off)";
  }
  void print_byte_status(std::ostream& out, const stream::ByteCounters& c) const override {
    print_line_status(out, device_, c);
  }

  // rs4sim.v1.GridScan at kAddress, and Observation for the event stream.
  ServiceList services(const ServiceContext& c) override {
    target_ = std::make_unique<rpc::LineDeviceTarget>(
        "gridscan", rpc::gridscan_watcher(kAddress, device_), c.clock, c.io);
    tap_.set_hub(target_->events(), kAddress);
    const rpc::LineContext line{c.executor, c.clock, kAddress, tap_, target_->events()};
    return {std::make_shared<rpc::GridScanService>(line, device_),
            std::make_shared<rpc::ObservationService>(rpc::RunContext{*target_, c.executor})};
  }
  void stop_services() override {
    if (target_) target_->stop();
  }

 private:
  gridscan::Options options_;
  gridscan::Device device_;
  bool mains_on_;
  rpc::TappedByteDevice tap_{device_};
  std::unique_ptr<rpc::LineDeviceTarget> target_;
};

// --link memory: the curtain alone on the simulated line (docs/gridscan.md "Simulated clock").
using GridScanSegment = LineSegment<gridscan::Device, rpc::GridScanService>;
const LineDevice<gridscan::Device> kGridScanLine{
    .kind = "gridscan",
    .protocol = stream::LineProtocol::kGridScan,
    .address = [](const gridscan::Device&) { return kAddress; },
    .watcher = rpc::gridscan_watcher,
    .print_status = print_line_status,
};

void validate(DeviceOptions& o) {
  refuse_unused(
      o, "gridscan",
      {DeviceFlag::kElements, DeviceFlag::kMode, DeviceFlag::kDoor, DeviceFlag::kBlocked,
       DeviceFlag::kMains});
  (void)gridscan_options(o);  // throws UsageError with the reason
}

}  // namespace

DeviceEntry gridscan_device_entry() {
  return {
      .name = "gridscan",
      .validate = validate,
      .build =
          [](const DeviceOptions& o) {
            return std::make_unique<GridScanInstance>(gridscan_options(o), o.mains != "off");
          },
      .simulate =
          [](const DeviceOptions& o) {
            auto segment = std::make_unique<GridScanSegment>(kGridScanLine, gridscan_options(o));
            // --mains off: dark until GridScan.SetPower / PowerCycle (the device powers up at
            // the line's first call unless power_off() came first).
            if (o.mains == "off") segment->device().power_off();
            return segment;
          },
      .demo = run_gridscan_demo,
      .byte_device = true,
  };
}

}  // namespace rs4sim::app
