#pragma once
// The earliest of up to 128 station deadlines, kept in a tournament tree: changing one
// deadline costs 7 comparisons, reading the earliest costs none. MemoryBus asks for the
// earliest deadline after every event; a scan over every attached station there made the
// 125-slave cycle quadratic. Ties go to the lower slot (the bus uses attach order, so runs
// stay deterministic). A slot without a deadline holds the largest tick count, so each
// comparison is one integer compare (the bus sets a deadline after every telegram); the rare
// deadline at TimePoint::max() itself is found by a scan when nothing earlier is set.

#include "dp/time/clock.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>

namespace rs4sim::dp::link {

class DeadlineTree {
 public:
  static constexpr std::size_t kSlots = 128;

  DeadlineTree() {
    key_.fill(kNone);
    for (std::size_t i = 0; i < kSlots; ++i) winner_[kSlots + i] = static_cast<std::uint8_t>(i);
    for (std::size_t p = kSlots - 1; p >= 1; --p) winner_[p] = winner_[2 * p];
  }

  // Sets (or clears, nullopt) the deadline of `slot` (< kSlots).
  void set(std::size_t slot, std::optional<TimePoint> deadline) {
    if (at_max_[slot]) --at_max_count_;
    at_max_[slot] = deadline == TimePoint::max();
    if (at_max_[slot]) ++at_max_count_;
    const TimePoint::rep key = deadline ? deadline->time_since_epoch().count() : kNone;
    // The front moving earlier (the master's reply in: its next send is sooner than the slot
    // time it waited for) stays the winner on its whole path: nothing else changes.
    const bool front_earlier = winner_[1] == slot && key <= key_[slot];
    key_[slot] = key;
    if (front_earlier) return;
    for (std::size_t p = (kSlots + slot) / 2; p >= 1; p /= 2) {
      const std::uint8_t l = winner_[2 * p];
      const std::uint8_t r = winner_[2 * p + 1];
      // Every slot on the left is lower than every slot on the right: a tie keeps the left.
      winner_[p] = key_[r] < key_[l] ? r : l;
    }
  }

  // The earliest deadline and its slot; nullopt when no slot has one.
  [[nodiscard]] std::optional<std::pair<TimePoint, std::size_t>> earliest() const {
    const std::uint8_t w = winner_[1];
    if (key_[w] != kNone) return std::pair{TimePoint{TimePoint::duration{key_[w]}}, std::size_t{w}};
    for (std::size_t i = 0; at_max_count_ != 0 && i < kSlots; ++i) {
      if (at_max_[i]) return std::pair{TimePoint::max(), i};
    }
    return std::nullopt;
  }

 private:
  static constexpr TimePoint::rep kNone = std::numeric_limits<TimePoint::rep>::max();

  std::array<TimePoint::rep, kSlots> key_{};  // ticks since the epoch, kNone = none (or max)
  std::array<bool, kSlots> at_max_{};         // the deadline is TimePoint::max()
  std::size_t at_max_count_ = 0;
  std::array<std::uint8_t, 2 * kSlots> winner_{};  // [1] = root; leaves at kSlots + slot
};

}  // namespace rs4sim::dp::link
