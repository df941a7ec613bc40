#pragma once
// Serial link: a tty (RS-485 adapter, or either side of a pseudo-terminal) carried by
// asio::serial_port, in PROFIBUS character format 8E1 at a standard rate
// ([IEC 61158-4-3 UART character] [IEC 61158-2 baud rates]; see serial_settings.h for how refused
// settings are handled).

#include "dp/link/serial_settings.h"
#include "dp/link/transport.h"

#include <boost/asio/serial_port.hpp>
#include <boost/asio/steady_timer.hpp>

#include <array>
#include <deque>
#include <string>
#include <vector>

namespace rs4sim::dp::link {

class SerialTransport final : public Transport {
 public:
  // Opens `path` and configures it; throws LinkException (kOpenFailed, kNotATerminal,
  // kAdapterRefusedBaudRate, kAdapterRefusedFormat).
  SerialTransport(boost::asio::io_context& io, const std::string& path, BaudRate baud,
                  const LogFn& log = {});
  // Takes ownership of an open tty descriptor (e.g. PseudoTerminal::release_master()).
  SerialTransport(boost::asio::io_context& io, int fd, BaudRate baud, const std::string& name,
                  const LogFn& log = {});
  ~SerialTransport() override;

  [[nodiscard]] bool datagram() const override { return false; }
  void start(BytesFn on_bytes, ErrorFn on_error) override;
  void send(std::span<const std::uint8_t> frame) override;
  void close() override;

  [[nodiscard]] const SerialSetup& setup() const { return setup_; }

 private:
  void read_next();
  void write_next();

  boost::asio::serial_port port_;
  boost::asio::steady_timer retry_timer_;
  SerialSetup setup_;
  BytesFn on_bytes_;
  ErrorFn on_error_;
  std::array<std::uint8_t, 512> rx_{};
  std::deque<std::vector<std::uint8_t>> tx_;
  bool writing_ = false;
};

}  // namespace rs4sim::dp::link
