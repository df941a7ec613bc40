#include "stream/memory_line.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace rs4sim::stream {

namespace {
// A device that keeps a deadline at or before `now` after on_time() would stall the line.
constexpr int kMaxStepsAtOneTime = 100000;

void keep_earliest(std::optional<TimePoint>& earliest, std::optional<TimePoint> t) {
  if (t && (!earliest || *t < *earliest)) earliest = t;
}
}  // namespace

MemoryLine::MemoryLine(ManualClock& clock, ByteDevice& device)
    : clock_(clock), device_(device), peer_free_(clock.now()), device_free_(clock.now()) {
  device_.set_wake_handler([this] {
    if (in_call_) return;  // read after the call anyway
    deadline_ = device_.next_deadline();
    drain();
  });
}

MemoryLine::~MemoryLine() { device_.set_wake_handler({}); }

void MemoryLine::start() {
  in_call_ = true;
  device_.on_time(clock_.now());
  in_call_ = false;
  deadline_ = device_.next_deadline();
  drain();
}

void MemoryLine::write(std::span<const std::uint8_t> bytes, Pacing pacing) {
  const LineSettings line = device_.line_settings();
  const TimePoint start = std::max(clock_.now(), peer_free_);
  peer_free_ = start + character_time(line, static_cast<double>(bytes.size()));
  if (pacing == Pacing::kWhole) {
    deliver_at(bytes, peer_free_);
    return;
  }
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    deliver_at(bytes.subspan(i, 1), start + character_time(line, static_cast<double>(i + 1)));
  }
}

void MemoryLine::write_damaged(std::uint8_t byte) {
  const TimePoint start = std::max(clock_.now(), peer_free_);
  peer_free_ = start + character_time(device_.line_settings(), 1.0);
  Chunk chunk{{byte}, peer_free_, true};
  const auto pos = std::upper_bound(to_device_.begin(), to_device_.end(), chunk.at,
                                    [](TimePoint t, const Chunk& c) { return t < c.at; });
  to_device_.insert(pos, std::move(chunk));
}

void MemoryLine::deliver_at(std::span<const std::uint8_t> bytes, TimePoint at) {
  Chunk chunk{{bytes.begin(), bytes.end()}, std::max(at, clock_.now()), false};
  const auto pos = std::upper_bound(to_device_.begin(), to_device_.end(), chunk.at,
                                    [](TimePoint t, const Chunk& c) { return t < c.at; });
  to_device_.insert(pos, std::move(chunk));
}

std::optional<TimePoint> MemoryLine::next_arrival() const {
  if (to_peer_.empty()) return std::nullopt;
  return to_peer_.front().end;
}

std::optional<TimePoint> MemoryLine::next_event() const {
  std::optional<TimePoint> earliest = deadline_;
  if (!to_device_.empty()) keep_earliest(earliest, to_device_.front().at);
  keep_earliest(earliest, next_arrival());
  return earliest;
}

void MemoryLine::run_until(TimePoint until) { (void)run_until(until, {}); }

bool MemoryLine::run_until(TimePoint until, const std::function<bool()>& done) {
  if (done && done()) return true;
  int steps_at_now = 0;
  TimePoint last = clock_.now();
  for (auto next = next_event(); next && *next <= until; next = next_event()) {
    const TimePoint now = std::max(*next, clock_.now());
    steps_at_now = now == last ? steps_at_now + 1 : 0;
    if (steps_at_now > kMaxStepsAtOneTime) {
      throw std::logic_error("MemoryLine: the device keeps a deadline in the past");
    }
    last = now;
    clock_.set(now);
    step(now);
    if (done && done()) return true;
  }
  if (until > clock_.now()) clock_.set(until);
  return done && done();
}

void MemoryLine::step(TimePoint now) {
  in_call_ = true;
  while (!to_device_.empty() && to_device_.front().at <= now) {
    const Chunk chunk = std::move(to_device_.front());
    to_device_.pop_front();
    if (chunk.damaged) {
      ++counters_.damaged_received;
      device_.on_damaged_byte(chunk.bytes.front(), now);
      deadline_ = device_.next_deadline();
      continue;
    }
    ++counters_.chunks_received;
    counters_.bytes_received += chunk.bytes.size();
    if (tap_) tap_(chunk.bytes, now, FrameDirection::kReceived);
    device_.on_bytes(chunk.bytes, now);
    deadline_ = device_.next_deadline();
  }
  if (deadline_ && *deadline_ <= now) device_.on_time(now);
  deadline_ = device_.next_deadline();
  in_call_ = false;
  drain();
  while (!to_peer_.empty() && to_peer_.front().end <= now) {
    LineFrame frame = std::move(to_peer_.front());
    to_peer_.pop_front();
    if (peer_) {
      peer_(frame);
    } else {
      received_.push_back(std::move(frame));
    }
  }
}

void MemoryLine::drain() {
  const TimePoint now = clock_.now();
  while (auto frame = device_.take_transmit()) {
    ++counters_.frames_sent;
    counters_.bytes_sent += frame->size();
    if (tap_) tap_(*frame, now, FrameDirection::kSent);
    const TimePoint start = std::max(now, device_free_);
    device_free_ =
        start + character_time(device_.line_settings(), static_cast<double>(frame->size()));
    to_peer_.push_back(LineFrame{std::move(*frame), start, device_free_});
  }
}

std::vector<LineFrame> MemoryLine::take_received() { return std::exchange(received_, {}); }

}  // namespace rs4sim::stream
