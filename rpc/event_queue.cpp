#include "rpc/event_queue.h"

#include <algorithm>

namespace rs4sim::rpc {

EventQueue::EventQueue(std::size_t capacity, bool telegrams, std::vector<std::uint8_t> addresses)
    : capacity_(std::clamp(capacity, kMinCapacity, kMaxCapacity)),
      telegrams_(telegrams),
      addresses_(std::move(addresses)) {}

bool EventQueue::watches(std::uint8_t address) const noexcept {
  return addresses_.empty() ||
         std::find(addresses_.begin(), addresses_.end(), address) != addresses_.end();
}

void EventQueue::push(v1::Event e) {
  {
    const std::lock_guard lock(mutex_);
    if (closed_) return;
    if (events_.size() >= capacity_) {
      ++dropped_;
      ++dropped_total_;
      return;
    }
    // The gap first: the client sees where events were lost (one slot beyond the capacity).
    if (dropped_ != 0) push_dropped_locked(e.now_ns());
    e.set_sequence(++sequence_);
    events_.push_back(std::move(e));
  }
  ready_.notify_one();
}

void EventQueue::push_dropped_locked(std::int64_t now_ns) {
  v1::Event gap;
  gap.set_sequence(++sequence_);
  gap.set_now_ns(now_ns);
  gap.mutable_dropped()->set_count(dropped_);
  events_.push_back(std::move(gap));
  dropped_ = 0;
}

std::vector<v1::Event> EventQueue::pop(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  ready_.wait_for(lock, timeout, [this] { return !events_.empty() || closed_; });
  std::vector<v1::Event> out;
  out.swap(events_);
  return out;
}

std::uint64_t EventQueue::dropped_total() const {
  const std::lock_guard lock(mutex_);
  return dropped_total_;
}

}  // namespace rs4sim::rpc
