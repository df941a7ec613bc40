#include "dp/link/station_runner.h"

#include <boost/asio/error.hpp>

namespace rs4sim::dp::link {

StationRunner::StationRunner(boost::asio::io_context& io, const Clock& clock, Transport& transport,
                             RunnerOptions options)
    : clock_(clock),
      transport_(transport),
      options_(options),
      timer_(io),
      idle_timer_(io),
      wake_(io.get_executor(), [this] {
        now_ = clock_.now();
        drain_all();
        arm_timer();
      }) {
  encode_buf_.reserve(fdl::kMaxTelegramSize);
}

void StationRunner::add(Station& station) {
  stations_.push_back(&station);
  turnaround_.emplace_back();
  station.set_wake_handler(wake_.handler());  // a no-op once the runner is gone
}

void StationRunner::start() {
  running_ = true;
  wake_.set_enabled(true);
  transport_.start([this](std::span<const std::uint8_t> b) { on_bytes(b); },
                   [this](std::error_code e) { on_transport_error(e); });
  now_ = clock_.now();
  for (Station* s : stations_) s->on_time(now_);
  drain_all();
  arm_timer();
}

void StationRunner::stop() {
  running_ = false;
  wake_.set_enabled(false);
  timer_.cancel();
  idle_timer_.cancel();
  transport_.close();
}

void StationRunner::on_bytes(std::span<const std::uint8_t> bytes) {
  if (!running_) return;
  now_ = clock_.now();
  received_ = false;
  decoder_.feed(bytes, *this);
  if (transport_.datagram()) {
    decoder_.idle(*this);  // one datagram = one telegram: a leftover is a truncated frame
  } else if (decoder_.pending_bytes() > 0) {
    arm_idle_timer();
  }
  const TimePoint request_end = now_;
  drain_all(received_ ? &request_end : nullptr);
  arm_timer();
}

const TurnaroundStats* StationRunner::turnaround(std::uint8_t address) const {
  for (std::size_t i = 0; i < stations_.size(); ++i) {
    if (stations_[i]->address() == address) return &turnaround_[i];
  }
  return nullptr;
}

void StationRunner::on_telegram(const fdl::Telegram& t) {
  ++counters_.received;
  received_ = true;
  if (tap_) {
    tap_buf_.clear();
    fdl::encode(t, tap_buf_);
    tap_(tap_buf_, now_, FrameDirection::kReceived);
  }
  for (Station* s : stations_) s->on_telegram(t, now_);
}

void StationRunner::on_decode_error(std::error_code e) {
  ++counters_.malformed;
  for (Station* s : stations_) s->on_malformed_frame(e);  // Station contract step 4
}

void StationRunner::on_transport_error(std::error_code e) {
  last_error_ = e;
  ++counters_.send_errors;
}

namespace {
// A reply (short acknowledgement, or a frame whose FC has the request bit clear), not a
// request or a token.
bool is_reply(const fdl::Telegram& t) {
  if (t.type == fdl::FrameType::kShortAck) return true;
  return t.type != fdl::FrameType::kToken && !t.fc.is_request();
}
}  // namespace

void StationRunner::drain_all(const TimePoint* request_end) {
  for (std::size_t i = 0; i < stations_.size(); ++i) {
    while (const fdl::Telegram* t = stations_[i]->next_transmit(tx_scratch_)) {
      ++counters_.sent;
      encode_buf_.clear();
      fdl::encode(*t, encode_buf_);
      if (request_end != nullptr && is_reply(*t)) {
        send_reply(i, *request_end);
        continue;
      }
      if (tap_) tap_(encode_buf_, now_, FrameDirection::kSent);
      transport_.send(encode_buf_);
    }
  }
}

void StationRunner::send_reply(std::size_t station, const TimePoint& request_end) {
  TurnaroundStats& stats = turnaround_[station];
  if (options_.slot_time) {
    const TimePoint leaving = clock_.now();
    if (leaving - request_end > *options_.slot_time) {
      stats.record_late();  // the master is already sending its retry: keep off the line
      return;
    }
  }
  if (tap_) tap_(encode_buf_, now_, FrameDirection::kSent);
  transport_.send(encode_buf_);
  if (options_.turnaround) stats.record(clock_.now() - request_end);
}

void StationRunner::arm_timer() {
  timer_.arm(stream::earliest_deadline(stations_), clock_, [this] {
    if (running_) on_timer();
  });
}

void StationRunner::on_timer() {
  now_ = clock_.now();
  for (Station* s : stations_) {
    const auto d = s->next_deadline();
    if (d && *d <= now_) s->on_time(now_);
  }
  drain_all();
  arm_timer();
}

void StationRunner::arm_idle_timer() {
  const std::uint64_t generation = ++idle_generation_;
  idle_timer_.expires_after(options_.idle_gap);
  idle_timer_.async_wait([this, generation](const boost::system::error_code& ec) {
    if (ec || !running_ || generation != idle_generation_) return;
    if (decoder_.pending_bytes() == 0) return;
    now_ = clock_.now();
    decoder_.idle(*this);  // [IEC 61158-4-3 bus parameters, timing]: a frame never spans an idle
                           // line
  });
}

}  // namespace rs4sim::dp::link
