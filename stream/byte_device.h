#pragma once
// The sans-I/O contract between a device on a byte stream (the RS-485/RS-232 devices:
// GridScan, METRON, Polaris, the RS4's own RS232 port) and a link, the byte-stream
// counterpart of dp::Station ([docs/design.md#sans-io-cores]).
//
// A link (serial port, pseudo-terminal, UDP, an in-memory line) owns the bytes and the
// real time; the device owns the protocol, including where its frames begin and end
// (by silence with stream::IdleGapFramer, by markers, or by length). The link:
//   1. passes received bytes with the time they arrived to on_bytes() (chunks as the OS
//      delivers them: part of a frame, or several frames), and a character received with a
//      parity or framing error to on_damaged_byte();
//   2. calls on_time() when next_deadline() has passed (e.g. an idle gap completed a
//      frame, a cycle ended, a streaming period elapsed);
//   3. after either call, drains take_transmit() and writes each frame whole, in order;
//   4. installs a wake handler: a device whose transmit queue or deadline changed outside
//      on_bytes()/on_time() (a scene change from the API, a power cycle) calls wake().
// Devices never block, sleep or read a clock; one event loop thread calls them.

#include "stream/clock.h"
#include "stream/line_settings.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace rs4sim::stream {

class ByteDevice {
 public:
  virtual ~ByteDevice() = default;

  // The character format the device runs with (a serial link configures the port with
  // it; pty, UDP and memory links carry bytes without one).
  [[nodiscard]] virtual LineSettings line_settings() const = 0;

  // Bytes arrived on the line at `now`.
  virtual void on_bytes(std::span<const std::uint8_t> bytes, TimePoint now) = 0;

  // Time has reached (or passed) next_deadline(); called at least once after start.
  virtual void on_time(TimePoint now) = 0;

  // When on_time() must be called next; nullopt = only when bytes arrive.
  [[nodiscard]] virtual std::optional<TimePoint> next_deadline() const = 0;

  // A character arrived damaged at `now` (parity or framing error; a serial link reports it
  // between the good bytes of on_bytes(), in line order). Default: dropped, as a port with
  // IGNPAR drops it; a device whose manual has a rule for it applies that instead (the METRON
  // rejects the whole message).
  virtual void on_damaged_byte(std::uint8_t byte, TimePoint now) {
    (void)byte;
    (void)now;
  }

  // The next frame to put on the line now, if any. The link calls this until nullopt.
  virtual std::optional<std::vector<std::uint8_t>> take_transmit() = 0;

  // Installed by the link the device is attached to; an empty handler detaches.
  void set_wake_handler(std::function<void()> handler) { wake_ = std::move(handler); }

 protected:
  // The transmit queue or next_deadline() changed outside on_bytes()/on_time().
  void wake() const {
    if (wake_) wake_();
  }

 private:
  std::function<void()> wake_;
};

}  // namespace rs4sim::stream
