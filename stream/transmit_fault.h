#pragma once
// The two transmit faults every byte device offers a controller to test its supervision
// with: a late answer and no answer at all ([docs/design.md#faults-are-controls]). They act on
// a device's frames as they go on the wire, after the device has built them; the faults of
// one protocol (a wrong CRC or checksum, a wrong sequence counter or node) stay with the
// device. Header-only, sans-I/O: the device owns the queue and the clock is injected.

#include "stream/clock.h"

#include <algorithm>
#include <cstdint>
#include <deque>
#include <optional>
#include <utility>
#include <vector>

namespace rs4sim::stream {

struct TransmitFault {
  bool silent = false;  // nothing goes out (communication loss)
  Duration late{0};     // every frame leaves this much after it is due (late answer)

  // The time a frame due at `due` goes on the wire.
  [[nodiscard]] TimePoint delay(TimePoint due) const { return due + late; }

  friend bool operator==(const TransmitFault&, const TransmitFault&) = default;
};

// Frames waiting for their time on the wire, in due order (equal times keep their order),
// with the TransmitFault applied as they are queued.
class TransmitQueue {
 public:
  using Bytes = std::vector<std::uint8_t>;

  // Queues `bytes` for `due` + fault.late; false (and nothing queued) when the fault is silent.
  bool schedule(Bytes bytes, TimePoint due, const TransmitFault& fault) {
    if (fault.silent) return false;
    const TimePoint at = fault.delay(due);
    const auto pos = std::upper_bound(pending_.begin(), pending_.end(), at,
                                      [](TimePoint t, const Entry& e) { return t < e.at; });
    pending_.insert(pos, Entry{at, std::move(bytes)});
    return true;
  }

  // The earliest time a queued frame is due, if any.
  [[nodiscard]] std::optional<TimePoint> next_due() const {
    if (pending_.empty()) return std::nullopt;
    return pending_.front().at;
  }

  // Moves the next frame due by `now` out of the queue, if any.
  std::optional<Bytes> pop_due(TimePoint now) {
    if (pending_.empty() || pending_.front().at > now) return std::nullopt;
    Bytes b = std::move(pending_.front().bytes);
    pending_.pop_front();
    return b;
  }

  void clear() { pending_.clear(); }
  [[nodiscard]] bool empty() const { return pending_.empty(); }
  [[nodiscard]] std::size_t size() const { return pending_.size(); }

 private:
  struct Entry {
    TimePoint at;
    Bytes bytes;
  };
  std::deque<Entry> pending_;
};

}  // namespace rs4sim::stream
