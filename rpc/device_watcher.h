#pragma once
// Watches one RS4 for the event stream (docs/rpc.md "Event stream"): on the loop thread,
// after bus activity or a timer tick, compares what the device shows now with what it
// showed last time and reports the differences as events. Reading the device's public
// views is all it does: no core is changed, locked or called from another thread.

#include "rs4/device/rs4_device.h"
#include "rs4sim/v1/rs4.pb.h"

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace rs4sim::rpc {

class DeviceWatcher {
 public:
  using Sink = std::function<void(v1::Event&&)>;

  DeviceWatcher(std::uint8_t address, const rs4::device::Rs4Device& device)
      : address_(address), device_(device) {}
  [[nodiscard]] std::uint8_t address() const noexcept { return address_; }

  // Reports every change since the last call to `sink`.
  void poll(std::int64_t now_ns, const Sink& sink);
  // Reports the state as of the last poll() whole (StateChange with from = "", the alarm
  // counts, the diagnosis) to `sink`: a new stream's first events.
  void snapshot(std::int64_t now_ns, const Sink& sink) const;

 private:
  static constexpr std::size_t kItems = 10;
  struct Look {
    std::array<std::string, kItems> items;
    std::uint32_t alarms_pending = 0;
    std::uint32_t alarms_outstanding = 0;
    bool error_active = false;
    std::vector<std::uint8_t> diagnosis;
  };
  [[nodiscard]] Look look() const;
  void report(const Look& now, std::int64_t now_ns, bool initial, const Sink& sink) const;
  [[nodiscard]] v1::Event event(std::int64_t now_ns) const;

  std::uint8_t address_;
  const rs4::device::Rs4Device& device_;
  Look last_;
};

}  // namespace rs4sim::rpc
