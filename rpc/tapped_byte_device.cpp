#include "rpc/tapped_byte_device.h"

namespace rs4sim::rpc {

TappedByteDevice::TappedByteDevice(stream::ByteDevice& inner) : inner_(inner) {
  // The core's wakes must reach the link this one is attached to.
  inner_.set_wake_handler([this] { wake(); });
}

void TappedByteDevice::on_bytes(std::span<const std::uint8_t> bytes, stream::TimePoint now) {
  now_ = now;
  if (hub_ != nullptr && hub_->wants_telegrams()) {
    hub_->telegram(address_, v1::DIRECTION_TO_STATION, bytes, "received", now);
  }
  inner_.on_bytes(bytes, now);
}

void TappedByteDevice::on_time(stream::TimePoint now) {
  now_ = now;
  inner_.on_time(now);
}

std::optional<std::vector<std::uint8_t>> TappedByteDevice::take_transmit() {
  auto frame = inner_.take_transmit();
  if (!frame) return frame;
  last_ = *frame;
  last_at_ = now_;
  if (hub_ != nullptr && hub_->wants_telegrams()) {
    hub_->telegram(address_, v1::DIRECTION_FROM_STATION, *frame, "sent", now_);
  }
  return frame;
}

}  // namespace rs4sim::rpc
