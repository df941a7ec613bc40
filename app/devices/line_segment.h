#pragma once
// The --link memory segment of a byte device (GridScan, METRON, Polaris): the device alone on
// the simulated line of a LineRun, driven through the API (docs/gridscan.md, docs/metron.md,
// docs/polaris.md "Simulated clock"). One class for the three; what differs is the device's
// LineDevice, a constant of its entry (device_gridscan.cpp, device_metron.cpp,
// device_polaris.cpp).

#include "app/devices/device_registry.h"
#include "app/devices/line_run.h"
#include "rpc/device_target.h"
#include "rpc/device_watcher.h"
#include "rpc/rs4_services.h"
#include "rpc/tapped_byte_device.h"

#include <cstdint>
#include <memory>
#include <ostream>
#include <utility>

namespace rs4sim::app {

// What a byte device's simulated segment needs from its entry.
template <typename Device>
struct LineDevice {
  stream::DeviceKind kind;        // kGridScan, kMetron, kPolaris (the description's)
  stream::LineProtocol protocol;  // what --capture decodes
  // The device's address on its line (its service's, and the summary's master address).
  std::uint8_t (*address)(const Device&);
  // The event-stream watcher (rpc::gridscan_watcher, ...).
  std::unique_ptr<rpc::Watcher> (*watcher)(std::uint8_t address, const Device&);
  // The status line at the end of a run.
  void (*print_status)(std::ostream&, const Device&, const stream::ByteCounters&);
};

// `Device` is the core (gridscan::Device, ...), `Service` its gRPC service, made from the
// line's context and the device (rpc::GridScanService, ...).
template <typename Device, typename Service>
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
  ServiceList services(const ServiceContext& c) override {
    return run_.services(c, line_.watcher(address_, device_),
                         [this](const rpc::LineContext& context) {
                           return std::make_shared<Service>(context, device_);
                         });
  }

 private:
  LineDevice<Device> line_;
  Device device_;
  std::uint8_t address_ = line_.address(device_);
  LineRun run_{line_.kind, address_, device_};
};

// The real-time part every byte device shares (pty, serial, UDP): its core behind a tap, its
// service and Observation over a LineDeviceTarget at its address, the end-of-run line. The
// device's instance adds its banner (describe()) and its signals.
template <typename Device, typename Service>
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
    target_ = std::make_unique<rpc::LineDeviceTarget>(line_.kind, line_.watcher(address, device_),
                                                      c.clock, c.io);
    tap_.set_hub(target_->events(), address);
    const rpc::LineContext line{c.executor, c.clock, address, tap_, target_->events()};
    return {std::make_shared<Service>(line, device_),
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

}  // namespace rs4sim::app
