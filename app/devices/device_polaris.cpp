// Device entry `polaris`: the virtual Optoscan Polaris measuring barrier with the RS485
// Modbus RTU output (polaris/device.h, docs/polaris.md), on pty, serial or UDP, 8N1 at
// 19200..115200 ([Polaris manual §8.1]). The flags fill a polaris::Options; its validate()
// has the last word.
//
//   rs4sim run --device polaris --link pty --model PL10 --beams 40 --mode FL4 --address 1
//   rs4sim run --device polaris --link memory --grpc 127.0.0.1:50051   (the simulated clock)
//              --baud 19200 --blocked 9-13,25-34
//   rs4sim run --device polaris --link pty --mode FL4,master,start=0,scan-time=20
//   --mode: a data mode (485MB | FL1 | FL4 | FL10), optionally followed by comma-separated
//           words, the PC tool's settings [Polaris manual §7.4.2] (polaris/mode_spec.h)
#include "app/devices/device_options.h"
#include "app/devices/device_registry.h"
#include "app/devices/line_segment.h"
#include "app/runtime/usage_error.h"
#include "modbus/rtu_frame.h"
#include "polaris/description.h"
#include "polaris/device.h"
#include "polaris/mode_spec.h"

#include <ostream>

namespace rs4sim::app {
namespace {

polaris::Options polaris_options(const DeviceOptions& o) {
  polaris::Options p;
  if (!o.model.empty()) {
    const auto f = polaris::parse_family(o.model);
    if (!f)
      throw UsageError("--model " + o.model + ": use PLi02, PLi05, PLi12, PL10, PL24 or PL48");
    p.family = *f;
  }
  if (o.beams) {
    if (*o.beams < 1 || *o.beams > 0xFFFF) {
      throw UsageError("--beams " + std::to_string(*o.beams) + ": out of range");
    }
    p.beams = static_cast<std::uint16_t>(*o.beams);
  }
  if (o.address) {
    if (!modbus::is_slave_address(*o.address)) {
      throw UsageError("--address " + std::to_string(*o.address) + ": a Modbus address is " +
                       std::to_string(modbus::kMinSlaveAddress) + ".." +
                       std::to_string(modbus::kMaxSlaveAddress) +
                       " [Modbus serial line V1.02 §2.2]");
    }
    p.address = static_cast<std::uint8_t>(*o.address);
  }
  if (o.baud) p.baud = *o.baud;
  if (!o.mode.empty()) {
    if (const auto why = polaris::apply_mode_spec(o.mode, p); !why.empty()) {
      throw UsageError("--mode " + o.mode + ": " + why);
    }
  }
  check_blocked(o, p.beams, "beams");
  if (o.blocked) {  // the initial scene, in the options as every line device's
    for (const int b : *o.blocked) p.blocked.push_back(static_cast<std::uint16_t>(b));
  }
  if (const auto why = p.validate(); !why.empty()) throw UsageError("polaris: " + why);
  return p;
}

// The status line at the end of a run.
void print_line_status(std::ostream& out, const polaris::Device& d, const stream::ByteCounters& c) {
  print_line_summary(out, polaris::description(), d.counters(),
                     ", calibrations " + std::to_string(d.calibrations()), c);
}

// The device on its line: alone on the simulated line with --link memory, driven through the API
// (docs/polaris.md "Simulated clock"), else on pty, serial or UDP (LineInstance); at its
// Modbus address.
const LineDevice<polaris::Device> kPolarisLine{
    .kind = polaris::description().kind,
    .protocol = polaris::description().link,
    .address = [](const polaris::Device& d) { return d.options().address; },
    .print_status = print_line_status,
};

class PolarisInstance final : public LineInstance<polaris::Device> {
 public:
  explicit PolarisInstance(const DeviceOptions& o)
      : LineInstance(kPolarisLine, polaris_options(o)) {}
  // SIGUSR1: the autocal input's pulse, an auto-calibration of 0.4 s per beam
  // [Polaris manual §7.2] (data reads answer exception 06 meanwhile); ignored while one runs.
  void on_user_signal(bool second, dp::TimePoint now) override {
    if (!second) (void)device_.start_calibration(now);
  }
  [[nodiscard]] std::string describe() const override {
    const auto& p = device_.options();
    return "Polaris " + std::string(polaris::to_string(p.family)) + " (" + std::to_string(p.beams) +
           " beams, " + std::string(polaris::to_string(p.mode)) + ", " +
           (p.role == polaris::Role::kSlave ? "Modbus slave " : "Modbus master to slave ") +
           std::to_string(p.address) + ", " + stream::to_string(device_.line_settings()) +
           "; SIGUSR1 starts an auto-calibration)";
  }
};

}  // namespace

DeviceEntry polaris_device_entry() {
  return line_device_entry<PolarisInstance>(polaris::description(), kPolarisLine, polaris_options,
                                            run_polaris_demo);
}

}  // namespace rs4sim::app
