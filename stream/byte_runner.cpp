#include "stream/byte_runner.h"

namespace rs4sim::stream {

ByteRunner::ByteRunner(boost::asio::io_context& io, const Clock& clock, Transport& transport)
    : clock_(clock), transport_(transport), timer_(io), wake_(io.get_executor(), [this] {
        now_ = clock_.now();
        drain_all();
        arm_timer();
      }) {}

void ByteRunner::add(ByteDevice& device) {
  devices_.push_back(&device);
  device.set_wake_handler(wake_.handler());
}

void ByteRunner::start() {
  running_ = true;
  wake_.set_enabled(true);
  transport_.set_damaged_handler([this](std::uint8_t b) { on_damaged(b); });
  transport_.start([this](std::span<const std::uint8_t> b) { on_bytes(b); },
                   [this](std::error_code e) { on_transport_error(e); });
  now_ = clock_.now();
  for (ByteDevice* d : devices_) d->on_time(now_);
  drain_all();
  arm_timer();
}

void ByteRunner::stop() {
  running_ = false;
  wake_.set_enabled(false);
  timer_.cancel();
  transport_.close();
}

void ByteRunner::on_bytes(std::span<const std::uint8_t> bytes) {
  if (!running_) return;
  now_ = clock_.now();
  ++counters_.chunks_received;
  counters_.bytes_received += bytes.size();
  if (tap_) tap_(bytes, now_, FrameDirection::kReceived);
  for (ByteDevice* d : devices_) d->on_bytes(bytes, now_);
  drain_all();
  arm_timer();
}

void ByteRunner::on_damaged(std::uint8_t byte) {
  if (!running_) return;
  now_ = clock_.now();
  ++counters_.damaged_received;
  for (ByteDevice* d : devices_) d->on_damaged_byte(byte, now_);
  drain_all();
  arm_timer();
}

void ByteRunner::on_transport_error(std::error_code e) {
  last_error_ = e;
  ++counters_.link_errors;
}

void ByteRunner::drain_all() {
  for (ByteDevice* d : devices_) {
    while (auto frame = d->take_transmit()) {
      ++counters_.frames_sent;
      counters_.bytes_sent += frame->size();
      if (tap_) tap_(*frame, now_, FrameDirection::kSent);
      transport_.send(*frame);
    }
  }
}

void ByteRunner::arm_timer() {
  timer_.arm(earliest_deadline(devices_), clock_, [this] {
    if (running_) on_timer();
  });
}

void ByteRunner::on_timer() {
  now_ = clock_.now();
  for (ByteDevice* d : devices_) {
    const auto deadline = d->next_deadline();
    if (deadline && *deadline <= now_) d->on_time(now_);
  }
  drain_all();
  arm_timer();
}

}  // namespace rs4sim::stream
