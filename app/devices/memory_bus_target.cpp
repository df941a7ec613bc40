#include "app/devices/memory_bus_target.h"

#include "app/devices/gsd_station_file.h"
#include "rpc/gsd_service.h"

#include <array>

namespace rs4sim::app {

MemoryBusTarget::MemoryBusTarget(dp::ManualClock& clock, dp::link::MemoryBus& bus,
                                 std::function<void()> drain, ServedStations stations)
    : clock_(clock), bus_(bus), drain_(std::move(drain)), stations_(std::move(stations)) {
  std::array<bool, 128> watched{};  // the addresses whose telegrams the stream carries
  for (const auto& r : stations_.rs4s) {
    hub_->watch(r.address, *r.device);
    watched[r.address & 127U] = true;
  }
  for (const GsdStation* g : stations_.gsd) {
    hub_->watch(rpc::gsd_watcher(*g));
    watched[g->address() & 127U] = true;
  }
  bus.add_observer([hub = hub_, watched, &clock](const dp::link::BusEvent& e) {
    if (hub->wants_telegrams()) {
      const auto fate = dp::link::to_string(e.fate);
      if (watched[e.from & 127U]) {
        hub->telegram(e.from, v1::DIRECTION_FROM_STATION, e.wire, fate, e.time);
      }
      if (e.to && watched[*e.to & 127U]) {
        hub->telegram(*e.to, v1::DIRECTION_TO_STATION, e.wire, fate, e.time);
      }
    }
    hub->poll(clock.now());
  });
}

std::vector<std::uint8_t> MemoryBusTarget::addresses() const {
  std::vector<std::uint8_t> out;
  if (stations_.rs4s.empty()) {
    for (const GsdStation* g : stations_.gsd) out.push_back(g->address());
  }
  for (const auto& r : stations_.rs4s) out.push_back(r.address);
  return out;
}

rs4::device::Rs4Device* MemoryBusTarget::device(std::uint8_t address) {
  for (const auto& r : stations_.rs4s) {
    if (r.address == address) return r.device;
  }
  return nullptr;
}

stream::DeviceKind MemoryBusTarget::kind() const {
  return stations_.rs4s.empty() ? stream::DeviceKind::kGeneric : stream::DeviceKind::kRs4;
}

std::vector<rpc::RunStation> MemoryBusTarget::stations() const {
  std::vector<rpc::RunStation> out;
  for (const auto& r : stations_.rs4s) out.push_back({r.address, stream::DeviceKind::kRs4});
  for (const GsdStation* g : stations_.gsd) {
    out.push_back({g->address(), stream::DeviceKind::kGeneric});
  }
  for (const auto& o : stations_.others) out.push_back({o.address, stream::DeviceKind::kGeneric});
  return out;
}

std::string MemoryBusTarget::other_station(std::uint8_t address) const {
  for (const GsdStation* g : stations_.gsd) {
    if (g->address() == address) return kGsdStationKind;
  }
  for (const auto& o : stations_.others) {
    if (o.address == address) return o.what;
  }
  return {};
}

bool MemoryBusTarget::run_until(const std::function<bool()>& done, dp::Duration limit) {
  const bool reached = bus_.run_until(done, clock_.now() + limit, drain_);
  hub_->poll(now());
  return reached;
}

void MemoryBusTarget::after(dp::Duration delay, std::function<void()> f) {
  bus_.run_until([] { return false; }, clock_.now() + delay, drain_);
  f();
  hub_->poll(now());
}

}  // namespace rs4sim::app
