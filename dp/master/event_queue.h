#pragma once
// Bounded queue of master events (events.h). When the owner stops draining it, the
// oldest events are dropped and counted rather than growing without limit.

#include "dp/master/events.h"

#include <cstdint>
#include <deque>
#include <vector>

namespace rs4sim::dp::master {

class EventQueue {
 public:
  static constexpr std::size_t kCapacity = 4096;

  void push(MasterEvent e) {
    if (events_.size() >= kCapacity) {
      events_.pop_front();
      ++dropped_;
    }
    events_.push_back(std::move(e));
  }
  void take(std::vector<MasterEvent>& out) {
    if (events_.empty()) return;  // the common case: drained after every link call
    for (auto& e : events_) out.push_back(std::move(e));
    events_.clear();
  }
  [[nodiscard]] std::size_t size() const { return events_.size(); }
  [[nodiscard]] std::uint64_t dropped() const { return dropped_; }

 private:
  std::deque<MasterEvent> events_;
  std::uint64_t dropped_ = 0;
};

}  // namespace rs4sim::dp::master
