#pragma once
// A watched device of the event stream (docs/rpc.md "Event stream"): on the loop thread, it
// reports what changed since its last poll, and its whole state for a new stream.
// DeviceWatcher watches an RS4, ItemsWatcher (rpc/items_watcher.h) the RS-485 devices.
//
// Watches one RS4 for the event stream: on the loop thread,
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

class Watcher {
 public:
  using Sink = std::function<void(v1::Event&&)>;
  virtual ~Watcher() = default;
  [[nodiscard]] virtual std::uint8_t address() const noexcept = 0;
  // Reports every change since the last call to `sink`.
  virtual void poll(std::int64_t now_ns, const Sink& sink) = 0;
  // Reports the state as of the last poll() whole (StateChange with from = "", and for the
  // RS4 the alarm counts and the diagnosis) to `sink`: a new stream's first events.
  virtual void snapshot(std::int64_t now_ns, const Sink& sink) const = 0;

 protected:
  Watcher() = default;
  Watcher(const Watcher&) = default;
  Watcher& operator=(const Watcher&) = default;
};

class DeviceWatcher final : public Watcher {
 public:
  DeviceWatcher(std::uint8_t address, const rs4::device::Rs4Device& device)
      : address_(address), device_(device) {}
  [[nodiscard]] std::uint8_t address() const noexcept override { return address_; }
  void poll(std::int64_t now_ns, const Sink& sink) override;
  void snapshot(std::int64_t now_ns, const Sink& sink) const override;

 private:
  static constexpr std::size_t kItems = 12;
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
