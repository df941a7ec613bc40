#include "rpc/service_support.h"

#include "dp/pdu/sap.h"
#include "rpc/event_hub.h"
#include "rpc/status.h"

#include <algorithm>
#include <string>

namespace rs4sim::rpc {
namespace {

std::string station_list(const RunTarget& target) {
  std::string out;
  for (const auto a : target.addresses()) out += (out.empty() ? "" : ", ") + std::to_string(a);
  return out;
}

// The run's devices in a message: "gsd" for GSD stations (their service is GsdStations),
// else the --device word.
std::string kind_word(stream::DeviceKind kind) {
  return kind == stream::DeviceKind::kGeneric ? "gsd" : std::string(stream::to_string(kind));
}

}  // namespace

grpc::Status unknown_station(const RunTarget& target, std::uint32_t address) {
  if (target.kind() != stream::DeviceKind::kRs4) {
    const auto kind = kind_word(target.kind());
    const auto here = target.addresses();
    if (std::find(here.begin(), here.end(), address) == here.end()) {
      return not_found("no " + kind + " at address " + std::to_string(address) + " (this run's " +
                       kind + ": " + station_list(target) + ")");
    }
    return failed_precondition("DEVICE_KIND", "address " + std::to_string(address),
                               "this run serves a " + kind + ", not an RS4 (stations: " +
                                   station_list(target) + "); use its own service");
  }
  const std::string rs4s = station_list(target);
  if (address < 256) {
    if (const auto what = target.other_station(static_cast<std::uint8_t>(address)); !what.empty()) {
      return failed_precondition(
          "DEVICE_KIND", "address " + std::to_string(address),
          what + ", not an RS4 (" + (rs4s.empty() ? "this run has none" : "RS4s: " + rs4s) + ")");
    }
  }
  return not_found("no RS4 at station " + std::to_string(address) + " (" +
                   (rs4s.empty() ? "this run has none" : "stations: " + rs4s) + ")");
}

grpc::Status on_device(const Rs4Context& c, std::uint32_t address, const DeviceFn& fn) {
  if (address > dp::pdu::sap::kMaxStationAddress) {
    return invalid_argument("address", "station address " + std::to_string(address) +
                                           " outside 0.." +
                                           std::to_string(dp::pdu::sap::kMaxStationAddress));
  }
  grpc::Status result;
  c.executor.run([&] {
    auto* device = c.target.device(static_cast<std::uint8_t>(address));
    if (device == nullptr) {
      result = unknown_station(c.target, address);
      return;
    }
    result = fn(*device, c.target.now());
    if (auto* hub = c.target.events()) hub->poll(c.target.now());  // the change, at once
  });
  return result;
}

grpc::Status on_device(const RunContext& c, std::uint32_t address, const DeviceFn& fn) {
  if (auto* rs4s = c.target.rs4s()) return on_device(Rs4Context{*rs4s, c.executor}, address, fn);
  if (address > dp::pdu::sap::kMaxStationAddress) {
    return invalid_argument("address", "station address " + std::to_string(address) +
                                           " outside 0.." +
                                           std::to_string(dp::pdu::sap::kMaxStationAddress));
  }
  grpc::Status result;
  c.executor.run([&] { result = unknown_station(c.target, address); });
  return result;
}

grpc::Status needs_simulated_clock() {
  return failed_precondition("CLOCK", "simulated time",
                             "this run is on the real-time clock; run the RS4 on the simulated "
                             "bus (rs4sim run --link memory --grpc ...) to control time");
}

grpc::Status needs_simulated_bus() {
  return failed_precondition("LINK", "bus faults",
                             "this run is on a real link; bus faults need the simulated bus "
                             "(--link memory)");
}

std::int64_t to_ns(dp::TimePoint t) {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(t.time_since_epoch()).count();
}

}  // namespace rs4sim::rpc
