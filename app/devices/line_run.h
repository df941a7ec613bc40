#pragma once
// What the in-memory runs of the RS-485 devices (GridScan, METRON, Polaris: `rs4sim run
// --device X --link memory [--grpc ...]`) share: the manual clock, the device's core behind
// its tap on an rpc::SimulatedLine, and the services of such a run (the device's own, with
// Exchange and Receive working; Observation; SimTime moving this clock). There is no client
// of ours on the line: without --grpc the device runs alone (the GridScan sends its power-up
// messages and, if told to, streams), with --grpc the harness is the client
// (docs/rpc.md "Exchange").

#include "app/devices/device_registry.h"
#include "rpc/line_service_support.h"
#include "rpc/line_target.h"
#include "rpc/tapped_byte_device.h"

#include <functional>
#include <memory>
#include <string>
#include <utility>

namespace rs4sim::app {

class LineRun {
 public:
  using MakeService = std::function<std::shared_ptr<grpc::Service>(const rpc::LineContext&)>;

  // `core` outlives this object. `kind`: kGridScan, kMetron, kPolaris.
  LineRun(stream::DeviceKind kind, std::uint8_t address, stream::ByteDevice& core);
  LineRun(const LineRun&) = delete;
  LineRun& operator=(const LineRun&) = delete;

  // Starts the line (once) and runs it for `d` of simulated time.
  void run_for(dp::Duration d);
  [[nodiscard]] const stream::ByteCounters& counters() const { return line_.counters(); }
  [[nodiscard]] dp::TimePoint now() const { return clock_.now(); }
  // Every frame on the line with its direction (--capture).
  void set_frame_tap(stream::FrameTap tap) { line_.line().set_frame_tap(std::move(tap)); }

  // The device's service from `make`, Observation and SimTime; the line starts now (its first
  // frames go to the event stream and to Receive).
  ServiceList services(const ServiceContext& c, std::unique_ptr<rpc::Watcher> watcher,
                       const MakeService& make);

 private:
  void start();

  stream::DeviceKind kind_;
  std::uint8_t address_;
  stream::ManualClock clock_;
  rpc::TappedByteDevice tap_;
  rpc::SimulatedLine line_;
  std::unique_ptr<rpc::SimulatedLineTarget> target_;
  bool started_ = false;
};

}  // namespace rs4sim::app
