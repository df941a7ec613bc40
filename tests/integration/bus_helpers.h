#pragma once
// Helpers shared by the DP integration tests.

#include "dp/devices/generic_bus.h"

#include <variant>

namespace rs4sim::integration {

using namespace std::chrono_literals;
using dp::Duration;
using dp::TimePoint;
using dp::devices::GenericBus;
using dp::devices::GenericBusConfig;
using dp::devices::GenericSlaveConfig;

// Slave `a` gets a configuration that varies with its address: 1…4 bytes in and out.
inline GenericSlaveConfig slave_config(std::uint8_t a) {
  const auto n = static_cast<std::uint8_t>(a % 4);  // length − 1
  return {a, static_cast<std::uint16_t>(0x1000 + a), {static_cast<std::uint8_t>(0x30 | n)}, true};
}

template <class E>
std::size_t count_events(const std::vector<dp::master::MasterEvent>& events, std::uint8_t address) {
  std::size_t n = 0;
  for (const auto& e : events) {
    if (const auto* x = std::get_if<E>(&e); x && x->address == address) ++n;
  }
  return n;
}

template <class E>
const E* last_event(const std::vector<dp::master::MasterEvent>& events) {
  for (auto it = events.rbegin(); it != events.rend(); ++it) {
    if (const auto* x = std::get_if<E>(&*it)) return x;
  }
  return nullptr;
}

}  // namespace rs4sim::integration
