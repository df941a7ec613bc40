#pragma once
// The --link memory segment of a byte device (GridScan, METRON, Polaris): the device alone on
// the simulated line of a LineRun, driven through the API (docs/gridscan.md, docs/metron.md,
// docs/polaris.md "Simulated clock"). One class for the three; what differs is the device's
// LineDevice, a constant of its entry (device_gridscan.cpp, device_metron.cpp,
// device_polaris.cpp).

#include "app/devices/device_options.h"
#include "app/devices/device_registry.h"
#include "app/devices/line_run.h"
#include "rpc/device_target.h"
#include "rpc/rs4_services.h"
#include "rpc/tapped_byte_device.h"

#include <cstdint>
#include <memory>
#include <ostream>
#include <string>
#include <utility>

namespace rs4sim::app {

// What a byte device's simulated segment needs from its entry; its service and event-stream
// watcher come from its kind's rpc::LineApi (rpc/line_devices.h).
template <typename Device>
struct LineDevice {
  stream::DeviceKind kind;        // the description's
  stream::LineProtocol protocol;  // the description's link: what --capture names
  // The device's address on its line (its service's, and the summary's master address).
  std::uint8_t (*address)(const Device&);
  // The status line at the end of a run.
  void (*print_status)(std::ostream&, const Device&, const stream::ByteCounters&);
};

// `Device` is the core (gridscan::Device, ...).
template <typename Device>
class LineSegment final : public SimulatedSegment {
 public:
  template <typename Options>
  LineSegment(const LineDevice<Device>& line, const Options& options)
      : line_(line), device_(options) {}

  // Before the run: the device (its scene from --blocked) and the simulated time.
  Device& device() { return device_; }
  [[nodiscard]] dp::TimePoint now() const { return run_.now(); }

  void run_for(dp::Duration d) override { run_.run_for(d); }
  [[nodiscard]] std::uint8_t master_address() const override { return address_; }
  void print_summary(std::ostream& out) const override {
    out << std::endl;
    line_.print_status(out, device_, run_.counters());
  }
  [[nodiscard]] bool healthy() const override { return true; }
  bool tap_line(stream::FrameTap tap) override {
    run_.set_frame_tap(std::move(tap));
    return true;
  }
  [[nodiscard]] stream::LineProtocol line_protocol() const override { return line_.protocol; }
  ServiceList services(const ServiceContext& c) override { return run_.services(c); }

 private:
  LineDevice<Device> line_;
  Device device_;
  std::uint8_t address_ = line_.address(device_);
  LineRun run_{line_.kind, address_, device_};
};

// The real-time part every byte device shares (pty, serial, UDP): its core behind a tap, its
// service and Observation over a LineDeviceTarget at its address, the end-of-run line. The
// device's instance adds its banner (describe()) and its signals.
template <typename Device>
class LineInstance : public DeviceInstance {
 public:
  template <typename Options>
  LineInstance(const LineDevice<Device>& line, const Options& options)
      : line_(line), device_(options) {}
  std::vector<stream::ByteDevice*> byte_devices() override { return {&tap_}; }
  [[nodiscard]] stream::LineProtocol line_protocol() const override { return line_.protocol; }
  void print_byte_status(std::ostream& out, const stream::ByteCounters& c) const override {
    line_.print_status(out, device_, c);
  }
  // The device's service at its address, and Observation for the event stream.
  ServiceList services(const ServiceContext& c) override {
    const std::uint8_t address = line_.address(device_);
    const auto& api = line_api(line_.kind);
    target_ = std::make_unique<rpc::LineDeviceTarget>(line_.kind, api.watcher(address, device_),
                                                      c.clock, c.io);
    tap_.set_hub(target_->events(), address);
    const rpc::LineContext line{c.executor, c.clock, address, tap_, target_->events()};
    return {api.make(line, device_),
            std::make_shared<rpc::ObservationService>(rpc::RunContext{*target_, c.executor})};
  }
  void stop_services() override {
    if (target_) target_->stop();
  }

 protected:
  LineDevice<Device> line_;
  Device device_;

 private:
  rpc::TappedByteDevice tap_{device_};
  std::unique_ptr<rpc::LineDeviceTarget> target_;
};

// The entry of a line device (app/devices/device_<name>.cpp, listed through
// RS4SIM_LINE_DEVICES): its word, options and kind from its description `d`; validate()
// refuses the options it does not take, then `checked` turns the others into the device's
// Options (UsageError with the reason); build() makes `Instance` from the DeviceOptions,
// simulate() a LineSegment of `line`; `demo` is its narrated demo (empty: none).
template <typename Instance, typename Device, typename Counters, typename Options>
DeviceEntry line_device_entry(const stream::DeviceDescription<Device, Counters>& d,
                              const LineDevice<Device>& line,
                              Options (*checked)(const DeviceOptions&),
                              decltype(DeviceEntry::demo) demo) {
  return {
      .name = std::string(d.name),
      .validate =
          [&d, checked](DeviceOptions& o) {
            refuse_unused(o, d.name, d.options);
            (void)checked(o);  // throws UsageError with the reason
          },
      .build = [](const DeviceOptions& o) { return std::make_unique<Instance>(o); },
      .simulate =
          [&line, checked](const DeviceOptions& o) {
            return std::make_unique<LineSegment<Device>>(line, checked(o));
          },
      .demo = std::move(demo),
      .byte_device = true,
      .options = d.options,
      .kind = d.kind,
  };
}

}  // namespace rs4sim::app
