// Device entry `echo`: the simplest byte device (stream/echo_device.h) sends every frame it
// receives back, cut by 3.5 characters of silence; checks a serial adapter, a pty client or
// a UDP peer. 9600 8N1 unless --baud/--format say otherwise.
//
//   rs4sim run --device echo --link pty --baud 115200 --format 8E1
#include "app/devices/device_options.h"
#include "app/devices/device_registry.h"
#include "stream/echo_device.h"

#include <array>
#include <ostream>

namespace rs4sim::app {
namespace {

constexpr stream::LineSettings kDefaultLine{9600, 8, stream::Parity::kNone, 1};

// The echo's options (it has no API, hence no counters or faults to describe).
constexpr std::array kOptions{
    stream::OptionInfo{"--baud", 50, 12000000, "the bit rate (default 9600)"},
    stream::OptionInfo{"--format", 1, 0, "the character format (default 8N1)"},
};

stream::EchoOptions echo_options(const DeviceOptions& o) {
  stream::EchoOptions e;
  e.line = line_settings(o, kDefaultLine);
  return e;
}

class EchoInstance final : public DeviceInstance {
 public:
  explicit EchoInstance(const DeviceOptions& o) : device_(echo_options(o)) {}
  std::vector<stream::ByteDevice*> byte_devices() override { return {&device_}; }
  [[nodiscard]] std::string describe() const override {
    return "echo device (" + stream::to_string(device_.line_settings()) +
           "; a frame ends after 3.5 characters of silence)";
  }
  void print_byte_status(std::ostream& out, const stream::ByteCounters& c) const override {
    out << "echo: frames echoed " << device_.frames_sent() << ", oversized "
        << device_.framer_stats().oversized << ", bytes received " << c.bytes_received << ", sent "
        << c.bytes_sent << ", link errors " << c.link_errors << std::endl;
  }

 private:
  stream::EchoDevice device_;
};

void validate(DeviceOptions& o) {
  refuse_unused(o, "echo", kOptions);
  (void)echo_options(o);  // throws UsageError for a bad --format
}

}  // namespace

DeviceEntry echo_device_entry() {
  return {
      .name = "echo",
      .validate = validate,
      .build = [](const DeviceOptions& o) { return std::make_unique<EchoInstance>(o); },
      .simulate = {},  // no in-memory link: --link memory is refused
      .demo = {},
      .byte_device = true,
      .options = kOptions,
      .kind = stream::DeviceKind::kEcho,
  };
}

}  // namespace rs4sim::app
