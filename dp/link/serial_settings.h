#pragma once
// Puts a tty file descriptor into PROFIBUS character format ([IEC 61158-4-3 UART character]
// [IEC 61158-2 baud rates]): 8 data bits, even parity, 1 stop bit, raw bytes, at a standard
// PROFIBUS rate.
//
// Standard termios speeds (B9600, B19200, B500000, B1500000, B3000000) are set with
// cfsetspeed; the others (45.45k, 93.75k, 187.5k, 6M, 12M) with Linux termios2/BOTHER.
// Every setting is read back: a real adapter that did not take the rate or the parity is an
// error (LinkException), while a pseudo-terminal, which has no line and may drop parity or
// the exact rate, only produces a note and carries on.

#include "dp/link/link_error.h"
#include "dp/time/baud_rate.h"

#include <functional>
#include <string>
#include <vector>

namespace rs4sim::dp::link {

using LogFn = std::function<void(const std::string&)>;

struct SerialSetup {
  bool is_pty = false;
  std::vector<std::string> notes;  // what a pty did not take (already passed to the log)
};

// True for a pseudo-terminal (either side).
[[nodiscard]] bool is_pseudo_terminal(int fd);

// Throws LinkException (kNotATerminal, kAdapterRefusedBaudRate, kAdapterRefusedFormat).
SerialSetup configure_serial(int fd, BaudRate baud, const std::string& name, const LogFn& log);

namespace detail {
// termios2/BOTHER (Linux): sets an arbitrary rate; returns 0 or errno. termios2_linux.cpp.
int set_custom_baud(int fd, std::uint32_t bps);
// Reads back the output rate in bit/s via termios2; 0 if unknown.
std::uint32_t read_baud(int fd);
}  // namespace detail

}  // namespace rs4sim::dp::link
