#pragma once
// An in-process line on the manual clock between one ByteDevice and a peer (test code, a
// benchmark, an in-process client): what the ByteRunner does on a real line, in simulated
// time and with the line's wire time ([docs/design.md#injected-time]).
//
//   * the peer write()s bytes at clock.now(): they go on the line after what the peer is
//     still sending and reach the device when the last one has arrived (character_time of
//     the device's LineSettings × length), in one chunk or one character at a time;
//   * the device's frames (take_transmit) go on the line one after the other and reach the
//     peer after their wire time (take_received(), or a callback);
//   * run_until(t) steps through deliveries and the device's deadlines in time order,
//     moving the clock to each, and leaves it at t.
// A device that wakes outside a call (a scene change) is drained at once. Like the ByteRunner's
// timer, the line reads the device's next_deadline() only after on_bytes()/on_time() and on a
// wake: a core that moves its deadline from outside a call without waking is called late
// (or early), here as on a real line ([stream/byte_device.h] point 4).

#include "stream/byte_counters.h"
#include "stream/byte_device.h"
#include "stream/clock.h"
#include "stream/frame_tap.h"

#include <cstdint>
#include <deque>
#include <functional>
#include <span>
#include <vector>

namespace rs4sim::stream {

// One frame on the line: its bytes, when its first bit went out and when its last arrived.
struct LineFrame {
  std::vector<std::uint8_t> bytes;
  TimePoint start{};
  TimePoint end{};
};

enum class Pacing : std::uint8_t {
  // The device gets the write in one chunk when its last byte has arrived. Two writes back
  // to back then arrive one wire time apart: a framer cutting by silence sees two frames.
  kWhole,
  // The device gets each byte when it has arrived: inter-character timing as on the wire.
  kPerCharacter,
};

class MemoryLine {
 public:
  MemoryLine(ManualClock& clock, ByteDevice& device);
  ~MemoryLine();
  MemoryLine(const MemoryLine&) = delete;
  MemoryLine& operator=(const MemoryLine&) = delete;

  // Calls on_time() once at clock.now() and drains (the link's start).
  void start();
  // The peer sends `bytes` starting at clock.now() (or when its previous write has left).
  void write(std::span<const std::uint8_t> bytes, Pacing pacing = Pacing::kWhole);
  // The peer sends one character that arrives damaged (a parity error on the line): the device
  // gets on_damaged_byte(byte) when it has arrived, in line order with the other writes.
  void write_damaged(std::uint8_t byte);
  // The device receives exactly `bytes` at `at` (≥ now), for tests that place chunks
  // themselves (a frame split across reads, a gap inside a frame).
  void deliver_at(std::span<const std::uint8_t> bytes, TimePoint at);
  // Steps deliveries and deadlines up to `until`; the clock ends at `until`.
  void run_until(TimePoint until);
  // Steps as run_until(until) but stops after the first step at whose end `done()` holds
  // (the clock stays at that step's time); returns done(). Checked once before any step.
  bool run_until(TimePoint until, const std::function<bool()>& done);
  void run_for(Duration d) { run_until(clock_.now() + d); }

  // Frames the device sent that have reached the peer, oldest first (and forgets them).
  std::vector<LineFrame> take_received();
  // Called for each device frame as it reaches the peer (instead of queueing it).
  void set_peer(std::function<void(const LineFrame&)> on_frame) { peer_ = std::move(on_frame); }
  void set_frame_tap(FrameTap tap) { tap_ = std::move(tap); }
  [[nodiscard]] const ByteCounters& counters() const { return counters_; }
  // The time the device's frames in flight take to arrive; nullopt when none is.
  [[nodiscard]] std::optional<TimePoint> next_arrival() const;
  // When the peer's transmitter is free again (its last write's last bit has gone out).
  [[nodiscard]] TimePoint peer_free() const { return peer_free_; }

 private:
  struct Chunk {
    std::vector<std::uint8_t> bytes;
    TimePoint at{};
    bool damaged = false;  // one character with a parity error
  };
  [[nodiscard]] std::optional<TimePoint> next_event() const;
  void step(TimePoint now);
  void drain();

  ManualClock& clock_;
  ByteDevice& device_;
  std::deque<Chunk> to_device_;      // sorted by `at`
  std::deque<LineFrame> to_peer_;    // sorted by `end`
  std::vector<LineFrame> received_;  // arrived at the peer, not yet taken
  TimePoint peer_free_{};            // the peer's transmitter is busy until then
  TimePoint device_free_{};          // the device's transmitter is busy until then
  std::function<void(const LineFrame&)> peer_;
  FrameTap tap_;
  ByteCounters counters_;
  bool in_call_ = false;
  std::optional<TimePoint> deadline_;  // the device's, as last read
};

}  // namespace rs4sim::stream
