#pragma once
// Cuts a byte stream into frames by silence, on the injected clock: a frame ends when the
// line has been idle for `gap` after its last byte. GridScan's RS485 protocol and Modbus
// RTU (t3.5, [Modbus serial line V1.02 §2.5.1.1]) delimit frames this way; give the gap in
// character times with stream::character_time().
//
// A link delivers bytes in chunks stamped with their arrival time; the framer treats
// bytes that arrive less than `gap` after the previous ones as the same frame. The owner
// calls poll() from on_time() when deadline() has passed (and after every feed()).

#include "stream/clock.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <span>
#include <vector>

namespace rs4sim::stream {

struct GapFrame {
  std::vector<std::uint8_t> bytes;  // at most max_frame bytes
  TimePoint first_byte{};           // arrival of the first chunk
  TimePoint last_byte{};            // arrival of the last chunk
  bool oversized = false;           // more than max_frame bytes arrived; the rest was dropped
};

struct FramerStats {
  std::uint64_t frames = 0;
  std::uint64_t oversized = 0;
  std::uint64_t bytes = 0;
};

class IdleGapFramer {
 public:
  IdleGapFramer(Duration gap, std::size_t max_frame);

  // Bytes arrived at `now`. If the line had been idle for `gap` since the pending frame's
  // last byte, that frame is complete and the bytes start a new one.
  void feed(std::span<const std::uint8_t> bytes, TimePoint now);

  // When the pending frame completes if nothing more arrives; nullopt when none pends.
  [[nodiscard]] std::optional<TimePoint> deadline() const;

  // The next complete frame at `now`, if any (oldest first).
  std::optional<GapFrame> poll(TimePoint now);

  // Drops everything received and pending (a device power cycle, a baud change).
  void reset();

  void set_gap(Duration gap) { gap_ = gap; }
  [[nodiscard]] Duration gap() const { return gap_; }
  [[nodiscard]] bool receiving() const { return pending_.has_value(); }
  [[nodiscard]] const FramerStats& stats() const { return stats_; }

 private:
  void complete_pending();

  Duration gap_;
  std::size_t max_frame_;
  std::optional<GapFrame> pending_;
  std::deque<GapFrame> ready_;
  FramerStats stats_;
};

}  // namespace rs4sim::stream
