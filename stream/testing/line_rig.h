#pragma once
// Test-only: one RS-485 device core on a stream::MemoryLine driven by its own manual clock,
// for the device tests and the fuzz targets (tests/gridscan, tests/metron, tests/polaris,
// fuzz/...). The line does the stepping ([stream/byte_device.h] points 1-4): deliveries and
// the device's deadlines in time order, its frames drained after every call and on a wake,
// each frame on the wire for its characters. So what a test sees is what a controller on
// the line sees:
//   * a frame has a start (its first bit on the wire: when the device gave it out, or when
//     its previous frame had left) and an end (its last bit arrived) -- it reaches the peer
//     only at its end, so a window that is to catch a reply must cover its wire time;
//   * two frames given out together go one after the other (the second starts at the
//     first's end).
// send() puts bytes at the device at once (no wire time, as a test that places a request
// at an exact time wants); write() sends them as the peer's transmitter would.
// The clock moves only through the rig (run_for, run_to, exchange), never by hand.

#include "stream/byte_device.h"
#include "stream/clock.h"
#include "stream/frame_tap.h"
#include "stream/memory_line.h"

#include <chrono>
#include <concepts>
#include <cstdint>
#include <deque>
#include <initializer_list>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace rs4sim::stream::testing {

template <typename Device>
requires std::derived_from<Device, ByteDevice>
class LineRig {
 public:
  // Builds the device from `args` and starts the line at the clock's epoch (on_time once,
  // the device's first frames drained).
  template <typename... Args>
  requires std::constructible_from<Device, Args...>
  explicit LineRig(Args&&... args) : LineRig(FrameTap{}, std::forward<Args>(args)...) {}

  // The same with `tap` on the line before it starts: it sees every frame the device gives
  // out, from the first, with the time it gave it out (FrameDirection::kSent), and every
  // chunk the device receives (kReceived). For fuzz targets whose invariants hold at the
  // moment of transmission (nothing sent while powered off).
  template <typename... Args>
  requires std::constructible_from<Device, Args...>
  explicit LineRig(FrameTap tap, Args&&... args)
      : device_(std::forward<Args>(args)...), line_(clock_, device_) {
    line_.set_peer([this](const LineFrame& f) { received_.push_back(f); });
    if (tap) line_.set_frame_tap(std::move(tap));
    line_.start();
  }

  LineRig(const LineRig&) = delete;
  LineRig& operator=(const LineRig&) = delete;

  // `bytes` reach the device now, in one chunk, and the line steps to now (the device has
  // read them when this returns; a reply it gives out at once is on the wire).
  void send(std::span<const std::uint8_t> bytes) {
    line_.deliver_at(bytes, clock_.now());
    line_.run_until(clock_.now());
  }
  void send(std::initializer_list<std::uint8_t> bytes) {
    send(std::span<const std::uint8_t>(bytes.begin(), bytes.size()));
  }
  // The peer's transmitter sends `bytes` from now (after its previous write): they reach
  // the device with their wire time, when the clock gets there (MemoryLine::write).
  void write(std::span<const std::uint8_t> bytes, Pacing pacing = Pacing::kWhole) {
    line_.write(bytes, pacing);
  }
  // One character that arrives damaged (a parity error), in line order with write().
  void write_damaged(std::uint8_t byte) { line_.write_damaged(byte); }

  // Steps deliveries and the device's deadlines up to now + d / t; the clock ends there.
  void run_for(Duration d) { line_.run_for(d); }
  void run_to(TimePoint t) { line_.run_until(t); }

  // Steps until a frame has reached the peer or `until` (the clock stops at that frame's
  // end); returns the oldest frame received and not taken, if any. Frames behind it stay.
  std::optional<LineFrame> run_until_received(TimePoint until) {
    line_.run_until(until, [this] { return !received_.empty(); });
    if (received_.empty()) return std::nullopt;
    LineFrame f = std::move(received_.front());
    received_.pop_front();
    return f;
  }

  // Forgets what has been received, sends `request` now (send()) and returns the frames that
  // reached the peer within `window` (a frame still on the wire at its end is not in it).
  std::vector<LineFrame> exchange(std::span<const std::uint8_t> request,
                                  Duration window = std::chrono::milliseconds(100)) {
    received_.clear();
    send(request);
    run_for(window);
    return take();
  }
  std::vector<LineFrame> exchange(std::initializer_list<std::uint8_t> request,
                                  Duration window = std::chrono::milliseconds(100)) {
    return exchange(std::span<const std::uint8_t>(request.begin(), request.size()), window);
  }

  // Sends `request` as exchange() does; true when the device gave out nothing within
  // `window`: nothing reached the peer and nothing is on the wire at its end.
  bool silent(std::span<const std::uint8_t> request,
              Duration window = std::chrono::milliseconds(100)) {
    return exchange(request, window).empty() && !on_the_wire();
  }
  bool silent(std::initializer_list<std::uint8_t> request,
              Duration window = std::chrono::milliseconds(100)) {
    return silent(std::span<const std::uint8_t>(request.begin(), request.size()), window);
  }
  // True when nothing has reached the peer since the last take() and nothing is on the wire:
  // the device has given out nothing since then (if the line was quiet at that take()).
  [[nodiscard]] bool quiet() const { return received_.empty() && !on_the_wire(); }

  // The frames that have reached the peer since the last take(), oldest first.
  std::vector<LineFrame> take() {
    std::vector<LineFrame> out(std::make_move_iterator(received_.begin()),
                               std::make_move_iterator(received_.end()));
    received_.clear();
    return out;
  }

  // Whether a frame the device gave out is still on the wire (sent, not yet arrived).
  [[nodiscard]] bool on_the_wire() const { return line_.next_arrival().has_value(); }

  [[nodiscard]] TimePoint now() const { return clock_.now(); }
  [[nodiscard]] const ManualClock& clock() const { return clock_; }
  Device& device() { return device_; }
  // The line itself (its counters, a tap); its peer is the rig's: set_peer() would bypass take().
  MemoryLine& line() { return line_; }

 private:
  ManualClock clock_;
  Device device_;
  std::deque<LineFrame> received_;
  MemoryLine line_;
};

}  // namespace rs4sim::stream::testing
