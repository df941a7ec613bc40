#include "metron/slave_receiver.h"

#include "metron/options.h"

namespace rs4sim::metron {

void SlaveReceiver::feed(std::span<const std::uint8_t> bytes, stream::TimePoint now) {
  expire(now);
  for (const auto b : bytes) {
    if (resync_until_ && now < *resync_until_) {
      ++stats_.resync_bytes;
      resync_until_ = now + config_.resync_gap;
      last_byte_completed_ = false;
      continue;
    }
    resync_until_.reset();
    take(b, now);
  }
}

void SlaveReceiver::take(std::uint8_t byte, stream::TimePoint now) {
  last_byte_completed_ = false;
  last_byte_ = now;
  if (field_ != Field::kStart) ++partial_.wire_bytes;
  switch (field_) {
    case Field::kStart:
      if (byte != config_.frame_start) {
        ++stats_.noise_bytes;
        return;
      }
      partial_ = SlaveMessage{};
      partial_.first_byte = now;
      partial_.wire_bytes = 1;
      body_read_ = 0;
      field_ = config_.node_mode ? Field::kAddress : Field::kLength;
      return;
    case Field::kAddress:
      partial_.address = byte;
      field_ = Field::kLength;
      return;
    case Field::kLength:
      partial_.length = byte;
      if (byte > kMaxLength) {
        partial_.length_too_long = true;
        ++stats_.too_long;
        resync_until_ = now + config_.resync_gap;
        complete();
        return;
      }
      field_ = byte == 0 ? Field::kChecksum : Field::kBody;
      return;
    case Field::kBody:
      partial_.body[body_read_++] = byte;
      if (body_read_ == partial_.length) field_ = Field::kChecksum;
      return;
    case Field::kChecksum:
      partial_.checksum = byte;
      partial_.checksum_ok =
          checksum(std::span<const std::uint8_t>(partial_.body).first(partial_.length),
                   config_.checksum_reading) == byte;
      complete();
      return;
  }
}

void SlaveReceiver::complete() {
  ready_.push_back(partial_);
  ++stats_.messages;
  field_ = Field::kStart;
  last_byte_completed_ = true;
}

void SlaveReceiver::mark_parity_error() {
  if (field_ != Field::kStart)
    partial_.parity_error = true;
  else if (last_byte_completed_ && !ready_.empty())
    ready_.back().parity_error = true;
}

void SlaveReceiver::expire(stream::TimePoint now) {
  if (field_ != Field::kStart && now - last_byte_ >= config_.receive_timeout) {
    ++stats_.truncated;
    field_ = Field::kStart;
  }
  if (resync_until_ && now >= *resync_until_) resync_until_.reset();
}

std::optional<SlaveMessage> SlaveReceiver::poll(stream::TimePoint now) {
  expire(now);
  if (ready_.empty()) return std::nullopt;
  auto m = ready_.front();
  ready_.pop_front();
  return m;
}

std::optional<stream::TimePoint> SlaveReceiver::deadline() const {
  if (field_ == Field::kStart) return std::nullopt;
  return last_byte_ + config_.receive_timeout;
}

void SlaveReceiver::reset() {
  field_ = Field::kStart;
  ready_.clear();
  resync_until_.reset();
  last_byte_completed_ = false;
}

}  // namespace rs4sim::metron
