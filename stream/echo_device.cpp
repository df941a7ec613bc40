#include "stream/echo_device.h"

#include "stream/transmit_queue.h"

namespace rs4sim::stream {

EchoDevice::EchoDevice(const EchoOptions& options)
    : options_(options),
      framer_(character_time(options.line, options.gap_characters), options.max_frame) {}

void EchoDevice::on_bytes(std::span<const std::uint8_t> bytes, TimePoint now) {
  framer_.feed(bytes, now);
  collect(now);
}

void EchoDevice::on_time(TimePoint now) { collect(now); }

void EchoDevice::collect(TimePoint now) {
  while (auto frame = framer_.poll(now)) {
    pending_.push_back({std::move(frame->bytes), now + options_.delay});
  }
  while (!pending_.empty() && pending_.front().due <= now) {
    transmit_.push_back(std::move(pending_.front().bytes));
    pending_.pop_front();
  }
}

std::optional<TimePoint> EchoDevice::next_deadline() const {
  std::optional<TimePoint> next = framer_.deadline();
  if (!pending_.empty() && (!next || pending_.front().due < *next)) next = pending_.front().due;
  return next;
}

std::optional<std::vector<std::uint8_t>> EchoDevice::take_transmit() {
  auto frame = take_front(transmit_);
  if (frame) ++sent_;
  return frame;
}

void EchoDevice::say(std::vector<std::uint8_t> frame) {
  transmit_.push_back(std::move(frame));
  wake();
}

}  // namespace rs4sim::stream
