#include "app/devices/device_registry.h"

#include <algorithm>
#include <utility>

namespace rs4sim::app {

const std::vector<DeviceEntry>& device_registry() {
  static const std::vector<DeviceEntry> registry = [] {
    std::vector<DeviceEntry> r{rs4_device_entry(), generic_device_entry(), echo_device_entry()};
    for (auto& e : line_device_entries()) r.push_back(std::move(e));
    return r;
  }();
  return registry;
}

const DeviceEntry* find_device(std::string_view name) {
  const auto& r = device_registry();
  const auto it =
      std::find_if(r.begin(), r.end(), [name](const DeviceEntry& e) { return e.name == name; });
  return it == r.end() ? nullptr : &*it;
}

const DeviceEntry& find_device(stream::DeviceKind kind) {
  const auto& r = device_registry();
  return *std::find_if(r.begin(), r.end(), [kind](const DeviceEntry& e) { return e.kind == kind; });
}

std::vector<std::string> device_names() {
  std::vector<std::string> names;
  for (const DeviceEntry& e : device_registry()) names.push_back(e.name);
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace rs4sim::app
