#pragma once
// Watches an RS-485 device (GridScan, METRON, Polaris) for the event stream (docs/rpc.md
// "Event stream"): `look` names what the device shows now as (what, value) pairs, always
// the same names in the same order; a change of a value is a StateChange. Like the RS4's
// DeviceWatcher it only reads the device's public views, on the loop thread.

#include "dp/time/clock.h"
#include "rpc/device_watcher.h"

#include <string>
#include <utility>
#include <vector>

namespace rs4sim::rpc {

class ItemsWatcher final : public Watcher {
 public:
  using Items = std::vector<std::pair<std::string, std::string>>;
  using Look = std::function<Items(dp::TimePoint now)>;

  ItemsWatcher(std::uint8_t address, Look look) : address_(address), look_(std::move(look)) {}
  [[nodiscard]] std::uint8_t address() const noexcept override { return address_; }
  void poll(std::int64_t now_ns, const Sink& sink) override;
  void snapshot(std::int64_t now_ns, const Sink& sink) const override;

 private:
  [[nodiscard]] v1::Event change(std::int64_t now_ns, const std::string& what,
                                 const std::string& from, const std::string& to) const;

  std::uint8_t address_;
  Look look_;
  Items last_;
};

}  // namespace rs4sim::rpc
