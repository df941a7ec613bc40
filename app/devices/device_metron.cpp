// Device entry `metron`: the virtual ReeR METRON measuring light curtain on RS-485
// (metron/device.h, docs/metron.md), on pty, serial or UDP. Slave line mode at
// 19200 8E1 by default; `--mode` switches to standard line mode with its reporting mode
// ([METRON manual "Serial line management"], metron/mode_spec.h).
//
//   rs4sim run --device metron --link pty --beams 24 --blocked 9-13
//   rs4sim run --device metron --link pty --node 5 --mode slave,input=enable-line
//   rs4sim run --device metron --link pty --mode periodical,hex,separator,checksum,period=250
//   rs4sim run --device metron --link memory --grpc 127.0.0.1:50051   (the simulated clock)
//   rs4sim run --device metron --link pty --wire-table trace.json  (byte values, layouts)
#include "app/devices/device_options.h"
#include "app/devices/device_registry.h"
#include "app/devices/line_segment.h"
#include "app/devices/metron_wire_file.h"
#include "app/runtime/usage_error.h"
#include "metron/description.h"
#include "metron/device.h"
#include "metron/mode_spec.h"

#include <ostream>

namespace rs4sim::app {
namespace {

metron::Options metron_options(const DeviceOptions& o) {
  metron::Options m;
  if (o.beams) {
    if (*o.beams < 1 || *o.beams > metron::kMaxBeams) {
      throw UsageError("--beams " + std::to_string(*o.beams) + ": the METRON has 1.." +
                       std::to_string(metron::kMaxBeams) + " beams here");
    }
    m.beams = static_cast<std::uint16_t>(*o.beams);
  }
  if (o.node) {
    if (*o.node < 0 || *o.node > metron::kMaxNode) {
      throw UsageError("--node " + std::to_string(*o.node) + ": a node is 0.." +
                       std::to_string(metron::kMaxNode) + " (" +
                       std::to_string(metron::kBroadcast) + " is the broadcast address)");
    }
    m.node_enabled = true;
    m.node = static_cast<std::uint8_t>(*o.node);
  }
  if (!o.mode.empty()) {
    if (const auto why = metron::apply_mode_spec(o.mode, m); !why.empty()) {
      throw UsageError("--mode " + o.mode + ": " + why);
    }
  }
  if (o.baud || !o.format.empty()) {
    if (m.line_mode == metron::LineMode::kSlave) {
      throw UsageError(
          "--baud/--format: slave line mode is fixed at 19200 8E1 "
          "[METRON manual \"Slave line mode\"]");
    }
    const auto line = line_settings(o, metron::line_settings(m));
    m.baud = line.baud;
    m.parity = line.parity;
  }
  if (!o.wire_table.empty()) m.wire = read_metron_wire_table(o.wire_table);
  check_blocked(o, m.beams, "beams");
  if (o.blocked) {  // the initial scene, in the options as every line device's
    for (const int b : *o.blocked) m.blocked.push_back(static_cast<std::uint16_t>(b));
  }
  if (const auto why = m.validate(); !why.empty()) throw UsageError("metron: " + why);
  return m;
}

// The status line at the end of a run.
void print_line_status(std::ostream& out, const metron::Device& d, const stream::ByteCounters& c) {
  print_line_summary(out, metron::description(), d.counters(), "", c);
}

// The device on its line: alone on the simulated line with --link memory, driven through the API
// (docs/metron.md "Simulated clock"), else on pty, serial or UDP (LineInstance); at its node
// number (node mode), else 0.
const LineDevice<metron::Device> kMetronLine{
    .kind = metron::description().kind,
    .protocol = metron::description().link,
    .address =
        [](const metron::Device& d) {
          return d.options().node_enabled ? d.options().node : std::uint8_t{0};
        },
    .print_status = print_line_status,
};

class MetronInstance final : public LineInstance<metron::Device> {
 public:
  explicit MetronInstance(const DeviceOptions& o) : LineInstance(kMetronLine, metron_options(o)) {}
  // SIGUSR1: the input line high, SIGUSR2: low (what the input type acts on).
  void on_user_signal(bool second, dp::TimePoint) override { device_.set_input(!second); }
  [[nodiscard]] std::string describe() const override {
    const auto& o = device_.options();
    return "METRON measuring light curtain (" + stream::to_string(device_.line_settings()) +
           ", input type " + std::string(metron::to_string(o.input_type)) +
           ": SIGUSR1 sets the input high, SIGUSR2 low)";
  }
};

}  // namespace

DeviceEntry metron_device_entry() {
  return line_device_entry<MetronInstance>(metron::description(), kMetronLine, metron_options,
                                           run_metron_demo);
}

}  // namespace rs4sim::app
