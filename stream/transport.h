#pragma once
// The byte side of a real-time link: a serial/pty stream or UDP datagrams, on an
// asio::io_context. A runner sits on top and drives the cores: dp/link/station_runner.h
// (PROFIBUS stations), stream/byte_runner.h (byte devices).

#include <cstdint>
#include <functional>
#include <span>
#include <system_error>

namespace rs4sim::stream {

class Transport {
 public:
  using BytesFn = std::function<void(std::span<const std::uint8_t>)>;
  using ErrorFn = std::function<void(std::error_code)>;
  using DamagedFn = std::function<void(std::uint8_t)>;

  virtual ~Transport() = default;
  // true: every receive is exactly one frame (UDP); false: a byte stream (serial/pty).
  [[nodiscard]] virtual bool datagram() const = 0;
  // Starts the receive loop; handlers run on the io_context thread.
  virtual void start(BytesFn on_bytes, ErrorFn on_error) = 0;
  // Characters the line received damaged (a parity or framing error), each on its own, in line
  // order between the good bytes; set before start(). Only a serial adapter with parity
  // reports them (SerialTransport: INPCK | PARMRK, stream/parity_marks.h); a pseudo-terminal
  // and UDP have no line and never call it. Without a handler they are dropped (IGNPAR), as
  // a port that checks parity does by default.
  virtual void set_damaged_handler(DamagedFn on_damaged) { (void)on_damaged; }
  // Queues one encoded frame; frames go out whole and in order.
  virtual void send(std::span<const std::uint8_t> frame) = 0;
  virtual void close() = 0;
};

}  // namespace rs4sim::stream
