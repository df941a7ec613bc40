#pragma once
// What the in-memory runs of the RS-485 devices (GridScan, METRON, Polaris: `rs4sim run
// --device X --link memory [--grpc ...]`) share: the manual clock, the device's core behind
// its tap on an rpc::SimulatedLine, and the services of such a run (the device's own, with
// Exchange and Receive working; Observation; SimTime moving this clock). There is no client
// of ours on the line: without --grpc the device runs alone (the GridScan sends its power-up
// messages and, if told to, streams), with --grpc the harness is the client
// (docs/rpc.md "Exchange").

#include "app/devices/device_registry.h"
#include "rpc/line_devices.h"
#include "rpc/line_service_support.h"
#include "rpc/line_target.h"
#include "rpc/tapped_byte_device.h"

#include <memory>
#include <string>
#include <utility>

namespace rs4sim::app {

// The gRPC side of a line device's kind (rpc/line_devices.h); std::logic_error for a kind
// that is no line device's (RS4SIM_LINE_DEVICES lists its service beside its entry).
const rpc::LineApi& line_api(stream::DeviceKind kind);

class LineRun {
 public:
  // `core` outlives this object. `kind`: a line device's (its description's).
  LineRun(stream::DeviceKind kind, std::uint8_t address, stream::ByteDevice& core);
  LineRun(const LineRun&) = delete;
  LineRun& operator=(const LineRun&) = delete;

  // Starts the line (once) and runs it for `d` of simulated time.
  void run_for(dp::Duration d);
  [[nodiscard]] const stream::ByteCounters& counters() const { return line_.counters(); }
  [[nodiscard]] dp::TimePoint now() const { return clock_.now(); }
  // Every frame on the line with its direction (--capture).
  void set_frame_tap(stream::FrameTap tap) { line_.line().set_frame_tap(std::move(tap)); }

  // The device's service and event-stream watcher (its kind's rpc::LineApi), Observation and
  // SimTime; the line starts now (its first frames go to the event stream and to Receive).
  ServiceList services(const ServiceContext& c);

 private:
  void start();

  stream::DeviceKind kind_;
  std::uint8_t address_;
  stream::ByteDevice& core_;
  stream::ManualClock clock_;
  rpc::TappedByteDevice tap_;
  rpc::SimulatedLine line_;
  std::unique_ptr<rpc::SimulatedLineTarget> target_;
  bool started_ = false;
};

}  // namespace rs4sim::app
