#pragma once
// The simplest ByteDevice: every frame it receives (cut by an idle gap, stream/
// idle_gap_framer.h) goes back on the line unchanged, `delay` after the frame ended. Used to
// check a serial line, a pty client or a link (`rs4sim run --device echo`), and by the
// stream/ tests of the runners.

#include "stream/byte_device.h"
#include "stream/idle_gap_framer.h"

#include <deque>

namespace rs4sim::stream {

struct EchoOptions {
  LineSettings line{9600, 8, Parity::kNone, 1};
  double gap_characters = 3.5;  // silence that ends a frame, in character times
  Duration delay{};             // after the frame's end, before the echo goes out
  std::size_t max_frame = 256;
};

class EchoDevice final : public ByteDevice {
 public:
  explicit EchoDevice(const EchoOptions& options = {});

  [[nodiscard]] LineSettings line_settings() const override { return options_.line; }
  void on_bytes(std::span<const std::uint8_t> bytes, TimePoint now) override;
  void on_time(TimePoint now) override;
  [[nodiscard]] std::optional<TimePoint> next_deadline() const override;
  std::optional<std::vector<std::uint8_t>> take_transmit() override;

  // Queues `frame` for sending now from outside a link call (wakes the link).
  void say(std::vector<std::uint8_t> frame);
  [[nodiscard]] const FramerStats& framer_stats() const { return framer_.stats(); }
  [[nodiscard]] std::uint64_t frames_sent() const { return sent_; }

 private:
  struct Pending {
    std::vector<std::uint8_t> bytes;
    TimePoint due{};
  };
  void collect(TimePoint now);

  EchoOptions options_;
  IdleGapFramer framer_;
  std::deque<Pending> pending_;  // frames waiting for their delay
  std::deque<std::vector<std::uint8_t>> transmit_;
  std::uint64_t sent_ = 0;
};

}  // namespace rs4sim::stream
