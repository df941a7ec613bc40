#pragma once
// Serial link: a tty (RS-485/RS-232 adapter, or either side of a pseudo-terminal) carried by
// asio::serial_port, in the character format of a stream::LineSettings (PROFIBUS: 8E1 at a
// standard rate, dp/link/profibus_line.h; see serial_settings.h for how refused settings are
// handled).

#include "stream/parity_marks.h"
#include "stream/serial_settings.h"
#include "stream/transport.h"

#include <boost/asio/serial_port.hpp>
#include <boost/asio/steady_timer.hpp>

#include <array>
#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace rs4sim::stream {

class SerialTransport final : public Transport {
 public:
  // Opens `path` and configures it; throws LinkException (kOpenFailed, kNotATerminal,
  // kAdapterRefusedBaudRate, kAdapterRefusedFormat).
  SerialTransport(boost::asio::io_context& io, const std::string& path, const LineSettings& line,
                  const LogFn& log = {});
  // Takes ownership of an open tty descriptor (e.g. PseudoTerminal::release_master()).
  SerialTransport(boost::asio::io_context& io, int fd, const LineSettings& line,
                  const std::string& name, const LogFn& log = {});
  ~SerialTransport() override;

  [[nodiscard]] bool datagram() const override { return false; }
  void start(BytesFn on_bytes, ErrorFn on_error) override;
  // With parity on a real adapter: the port marks damaged characters (PARMRK) and they come
  // here, decoded, in line order; a pseudo-terminal keeps dropping nothing (it has no line).
  // A port that refuses PARMRK keeps IGNPAR, with a note in the log.
  void set_damaged_handler(DamagedFn on_damaged) override;
  void send(std::span<const std::uint8_t> frame) override;
  void close() override;

  [[nodiscard]] const SerialSetup& setup() const { return setup_; }

  // How the frames went out. PROFIBUS allows no idle time between the characters of a
  // telegram ([IEC 61158-4-3 UART character]: a telegram's characters follow without a gap),
  // so send() hands each frame to the kernel in one write() at once; only when the kernel's
  // buffer cannot take it whole (a stalled line) is the rest written later, counted in `split`.
  struct WriteCounters {
    std::uint64_t frames = 0;  // frames handed to send()
    std::uint64_t whole = 0;   // written by one write() in send()
    std::uint64_t split = 0;   // needed more than one write() (or queued behind one that did)
    std::uint64_t errors = 0;  // write() failed (reported through the error handler)
  };
  [[nodiscard]] const WriteCounters& write_counters() const { return writes_; }

 private:
  void read_next();
  void write_next();

  boost::asio::serial_port port_;
  boost::asio::steady_timer retry_timer_;
  SerialSetup setup_;
  bool parity_ = false;  // the line has a parity bit
  LogFn log_;
  BytesFn on_bytes_;
  DamagedFn on_damaged_;
  std::optional<ParityMarks> marks_;  // set when the port marks damaged characters
  ErrorFn on_error_;
  std::array<std::uint8_t, 512> rx_{};
  std::deque<std::vector<std::uint8_t>> tx_;  // only after a short write: what is still to go
  bool writing_ = false;
  WriteCounters writes_;
};

}  // namespace rs4sim::stream
