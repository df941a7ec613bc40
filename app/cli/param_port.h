#pragma once
// The RS4's RS232 port on a serial device or pty (`rs4sim run --rs232 pty` prints
// /dev/pts/N): the Exchange of rs4/param_doc/rs232_set_client.h over a file descriptor, 8N1 at
// 57 600 baud ([docs/rs232.md]), each answer awaited up to a timeout, the 0x23 stream skipped.

#include "rs4/param_doc/rs232_set_client.h"

#include <chrono>
#include <string>

namespace rs4sim::app::param {

class SerialPort {
 public:
  // ParamCommandError when the device cannot be opened or is not a terminal.
  explicit SerialPort(const std::string& path,
                      std::chrono::milliseconds timeout = std::chrono::seconds(5));
  ~SerialPort();
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;

  // Sends one framed command and returns the first answer that is not a 0x23/0x54 telegram.
  std::optional<rs4::rs232::Answer> exchange(std::span<const std::uint8_t> frame);
  rs4::param_doc::Exchange exchanger() {
    return [this](std::span<const std::uint8_t> frame) { return exchange(frame); };
  }

 private:
  int fd_ = -1;
  std::chrono::milliseconds timeout_;
  rs4::rs232::AnswerReader reader_;
};

}  // namespace rs4sim::app::param
