#pragma once
// A stream::ByteDevice in front of an RS-485 device's core that keeps the last frame it sent
// (GetState's last_frame) and shows the event hub what goes over the line: every frame sent
// (DIRECTION_FROM_STATION) and every chunk of bytes received (DIRECTION_TO_STATION, as the OS
// delivered it: the core cuts frames itself). The core's wakes pass through to the link.

#include "rpc/event_hub.h"
#include "stream/byte_device.h"

#include <vector>

namespace rs4sim::rpc {

class TappedByteDevice final : public stream::ByteDevice {
 public:
  explicit TappedByteDevice(stream::ByteDevice& inner);
  TappedByteDevice(const TappedByteDevice&) = delete;
  TappedByteDevice& operator=(const TappedByteDevice&) = delete;
  // nullptr = no tap (until the run's gRPC services exist).
  void set_hub(EventHub* hub, std::uint8_t address) noexcept {
    hub_ = hub;
    address_ = address;
  }

  [[nodiscard]] stream::LineSettings line_settings() const override {
    return inner_.line_settings();
  }
  void on_bytes(std::span<const std::uint8_t> bytes, stream::TimePoint now) override;
  void on_time(stream::TimePoint now) override;
  [[nodiscard]] std::optional<stream::TimePoint> next_deadline() const override {
    return inner_.next_deadline();
  }
  std::optional<std::vector<std::uint8_t>> take_transmit() override;

  [[nodiscard]] const std::vector<std::uint8_t>& last_frame() const noexcept { return last_; }
  // The time of the link's call that took it; nullopt = nothing sent yet.
  [[nodiscard]] std::optional<stream::TimePoint> last_sent() const noexcept { return last_at_; }

 private:
  stream::ByteDevice& inner_;
  EventHub* hub_ = nullptr;
  std::uint8_t address_ = 0;
  stream::TimePoint now_{};  // of the last call: take_transmit() has no time of its own
  std::vector<std::uint8_t> last_;
  std::optional<stream::TimePoint> last_at_;
};

}  // namespace rs4sim::rpc
