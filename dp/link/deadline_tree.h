#pragma once
// The earliest of up to 128 station deadlines, kept in a tournament tree: changing one
// deadline costs 7 comparisons, reading the earliest costs none. MemoryBus asks for the
// earliest deadline after every event; a scan over every attached station there made the
// 125-slave cycle quadratic. Ties go to the lower slot (the bus uses attach order, so runs
// stay deterministic).

#include "dp/time/clock.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>

namespace rs4sim::dp::link {

class DeadlineTree {
 public:
  static constexpr std::size_t kSlots = 128;

  DeadlineTree() {
    for (std::size_t i = 0; i < kSlots; ++i) winner_[kSlots + i] = static_cast<std::uint8_t>(i);
    for (std::size_t p = kSlots - 1; p >= 1; --p) winner_[p] = winner_[2 * p];
  }

  // Sets (or clears, nullopt) the deadline of `slot` (< kSlots).
  void set(std::size_t slot, std::optional<TimePoint> deadline) {
    deadline_[slot] = deadline;
    for (std::size_t p = (kSlots + slot) / 2; p >= 1; p /= 2) {
      const std::uint8_t l = winner_[2 * p];
      const std::uint8_t r = winner_[2 * p + 1];
      winner_[p] = earlier(r, l) ? r : l;
    }
  }

  // The earliest deadline and its slot; nullopt when no slot has one.
  [[nodiscard]] std::optional<std::pair<TimePoint, std::size_t>> earliest() const {
    const std::uint8_t w = winner_[1];
    if (!deadline_[w]) return std::nullopt;
    return std::pair{*deadline_[w], std::size_t{w}};
  }

 private:
  // Strictly earlier; equal deadlines keep the left (lower) slot, which is the caller's
  // default, so r wins only when strictly earlier.
  [[nodiscard]] bool earlier(std::uint8_t a, std::uint8_t b) const {
    const auto& da = deadline_[a];
    const auto& db = deadline_[b];
    if (!da) return false;
    if (!db) return true;
    return *da < *db || (*da == *db && a < b);
  }

  std::array<std::optional<TimePoint>, kSlots> deadline_{};
  std::array<std::uint8_t, 2 * kSlots> winner_{};  // [1] = root; leaves at kSlots + slot
};

}  // namespace rs4sim::dp::link
