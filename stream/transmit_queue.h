#pragma once
// The transmit queue of a byte device: frames wait in order until the link takes them
// (ByteDevice::take_transmit(), called until nullopt).

#include <optional>
#include <utility>

namespace rs4sim::stream {

// Takes the oldest item off `queue` (a std::deque or std::queue-like container with front()
// and pop_front()); nullopt when it is empty.
template <class Queue>
[[nodiscard]] std::optional<typename Queue::value_type> take_front(Queue& queue) {
  if (queue.empty()) return std::nullopt;
  auto item = std::move(queue.front());
  queue.pop_front();
  return item;
}

}  // namespace rs4sim::stream
