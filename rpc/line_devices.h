#pragma once
// The gRPC side of the RS-485 line devices, the list RS4SIM_LINE_DEVICES of the root
// CMakeLists.txt (GridScan, METRON, Polaris): each device's rpc/<name>_service.cpp defines
// `LineApi <name>_line_api()`, and the build generates line_apis() from the list
// (rpc/line_apis.cpp.in), so that nothing else names a line device's service. The run's line
// entries (app/devices/line_segment.h) make the service and the event-stream watcher of their
// device through it; Run.Describe (rpc/run_service.cpp) names the service of a station's kind.

#include "rpc/device_watcher.h"
#include "rpc/line_service_support.h"
#include "stream/byte_device.h"
#include "stream/device_description.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace grpc {
class Service;
}

namespace rs4sim::rpc {

// One line device's service and watcher, over its core as a stream::ByteDevice.
struct LineApi {
  stream::DeviceKind kind;  // its description's
  std::string service;      // the service's full name, "rs4sim.v1.Metron"
  std::function<std::shared_ptr<grpc::Service>(const LineContext&, stream::ByteDevice&)> make;
  std::function<std::unique_ptr<Watcher>(std::uint8_t address, const stream::ByteDevice&)> watcher;
};

// The LineApi of `Service` (constructed from a LineContext and a Device&, serving the gRPC
// service `full_name`) and `watcher`, for the device `description` describes. The core the run
// hands it must be that Device (std::bad_cast otherwise: a kind's entry with another's core).
template <typename Service, typename Device, typename Counters>
LineApi line_api(const stream::DeviceDescription<Device, Counters>& description,
                 std::string full_name,
                 std::unique_ptr<Watcher> (*watcher)(std::uint8_t address, const Device&)) {
  return {description.kind, std::move(full_name),
          [](const LineContext& c, stream::ByteDevice& d) -> std::shared_ptr<grpc::Service> {
            return std::make_shared<Service>(c, dynamic_cast<Device&>(d));
          },
          [watcher](std::uint8_t address, const stream::ByteDevice& d) {
            return watcher(address, dynamic_cast<const Device&>(d));
          }};
}

// Every line device's API, in the order of RS4SIM_LINE_DEVICES (generated).
const std::vector<LineApi>& line_apis();
// The API of a kind; nullptr: not a line device.
const LineApi* find_line_api(stream::DeviceKind kind);

}  // namespace rs4sim::rpc
