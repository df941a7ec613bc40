#pragma once
// Drives stream::ByteDevice cores over a real-time Transport from one asio::io_context
// thread ([docs/design.md#one-event-loop], the ByteDevice contract in stream/byte_device.h),
// the byte-stream counterpart of dp/link/station_runner.h:
//   received bytes → on_bytes(bytes, now) of every device (an RS-485 line is multidrop; each
//   device frames and filters by address itself) → take_transmit() drained →
//   Transport::send(), one frame per call (UDP: one frame per datagram);
//   one steady_timer armed for the earliest next_deadline() → on_time().
// `now` always comes from the injected Clock (RealClock in production). A device that wakes
// outside a runner call gets one drain + timer re-arm posted to the loop (coalesced).

#include "stream/byte_counters.h"
#include "stream/byte_device.h"
#include "stream/coalesced_wake.h"
#include "stream/deadline_timer.h"
#include "stream/frame_tap.h"
#include "stream/transport.h"

#include <boost/asio/io_context.hpp>

#include <system_error>
#include <vector>

namespace rs4sim::stream {

class ByteRunner {
 public:
  ByteRunner(boost::asio::io_context& io, const Clock& clock, Transport& transport);
  ByteRunner(const ByteRunner&) = delete;
  ByteRunner& operator=(const ByteRunner&) = delete;

  // Adds a device (before start()) and installs its wake handler. The device must outlive
  // the runner or be detached by it (the handler is a no-op once the runner is gone).
  void add(ByteDevice& device);
  // Sees every received chunk (as the OS delivered it: part of a frame or several) and
  // every sent frame, with the runner's `now`.
  void set_frame_tap(FrameTap tap) { tap_ = std::move(tap); }
  // Starts receiving and calls on_time() once on every device.
  void start();
  // Stops the timer and closes the transport.
  void stop();
  [[nodiscard]] const ByteCounters& counters() const { return counters_; }
  [[nodiscard]] std::error_code last_error() const { return last_error_; }

 private:
  void on_bytes(std::span<const std::uint8_t> bytes);
  void on_damaged(std::uint8_t byte);
  void on_transport_error(std::error_code e);
  void on_timer();
  void drain_all();
  void arm_timer();

  const Clock& clock_;
  Transport& transport_;
  std::vector<ByteDevice*> devices_;
  DeadlineTimer timer_;
  CoalescedWake wake_;
  ByteCounters counters_;
  std::error_code last_error_;
  FrameTap tap_;
  TimePoint now_{};
  bool running_ = false;
};

}  // namespace rs4sim::stream
