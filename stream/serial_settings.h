#pragma once
// Puts a tty file descriptor into a stream::LineSettings character format: raw bytes, 5..8
// data bits, no/even/odd parity, 1 or 2 stop bits, at any rate (e.g. PROFIBUS's 8E1
// [IEC 61158-4-3 UART character], GridScan's 115200 8N1 [GridScan manual §9.1], METRON's
// 19200 8E1 [METRON manual "Slave line mode"]).
//
// Standard termios speeds (B9600 … B4000000) are set with cfsetspeed; any other rate (45.45k,
// 93.75k, 187.5k, 6M, 12M, …) with Linux termios2/BOTHER. With parity, a character with a
// parity error is dropped (INPCK | IGNPAR; mark_parity_errors() hands it to the device instead).
// Every setting is read back: a real adapter that
// did not take the rate or the format is an error (LinkException), while a pseudo-terminal,
// which has no line and may drop parity or the exact rate, only produces a note and carries on.
// A real adapter whose driver reports a rate within 2 % of the one asked for (it cannot divide
// its clock to the PROFIBUS rate exactly; CP210x has a fixed table) gets a warning in the notes
// and carries on: PROFIBUS asks for ±0.3 % [IEC 61158-2 baud rate tolerance] and a master may
// see character errors; further off, no UART at the other end can read the characters: an error.

#include "stream/line_settings.h"
#include "stream/link_error.h"
#include "stream/serial_adapter.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rs4sim::stream {

using LogFn = std::function<void(const std::string&)>;

struct SerialSetup {
  bool is_pty = false;
  std::vector<std::string> notes;  // what a pty did not take (already passed to the log)
  std::uint32_t actual_baud = 0;   // the rate the driver reports it set (termios2 readback)
  // A real adapter: low latency, RS-485 mode, the driver (SerialTransport sets it up).
  std::optional<AdapterSetup> adapter;
};

// Switches a configured port with parity from dropping damaged characters (IGNPAR) to marking
// them (INPCK | PARMRK, [termios(3) PARMRK]; stream/parity_marks.h decodes the marks), so a
// device can apply its own rule. Only for a real adapter: on a pseudo-terminal the master's
// termios are the slave's (Linux), so PARMRK would make the client's own reads double every FF.
// Returns false (errno set) when the port refused it or did not keep it.
bool mark_parity_errors(int fd);

// True for a pseudo-terminal (either side).
[[nodiscard]] bool is_pseudo_terminal(int fd);

// Throws LinkException (kNotATerminal, kAdapterRefusedBaudRate, kAdapterRefusedFormat).
SerialSetup configure_serial(int fd, const LineSettings& line, const std::string& name,
                             const LogFn& log);

namespace detail {
// termios2/BOTHER (Linux): sets an arbitrary rate; returns 0 or errno. termios2_linux.cpp.
int set_custom_baud(int fd, std::uint32_t bps);
// Reads back the output rate in bit/s via termios2; 0 if unknown.
std::uint32_t read_baud(int fd);
}  // namespace detail

}  // namespace rs4sim::stream
