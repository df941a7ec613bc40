#include "stream/serial_settings.h"

#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <termios.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <utility>

namespace rs4sim::stream {

namespace {

std::optional<speed_t> standard_speed(std::uint32_t bps) {
  static constexpr std::array<std::pair<std::uint32_t, speed_t>, 22> kSpeeds = {{
      {300, B300},         {1200, B1200},       {2400, B2400},       {4800, B4800},
      {9600, B9600},       {19200, B19200},     {38400, B38400},     {57600, B57600},
      {115200, B115200},   {230400, B230400},   {460800, B460800},   {500000, B500000},
      {576000, B576000},   {921600, B921600},   {1000000, B1000000}, {1152000, B1152000},
      {1500000, B1500000}, {2000000, B2000000}, {2500000, B2500000}, {3000000, B3000000},
      {3500000, B3500000}, {4000000, B4000000},
  }};
  for (const auto& [rate, speed] : kSpeeds) {
    if (rate == bps) return speed;
  }
  return std::nullopt;  // e.g. 45.45k, 93.75k, 187.5k, 6M, 12M: termios2
}

tcflag_t size_flag(std::uint8_t data_bits) {
  switch (data_bits) {
    case 5: return CS5;
    case 6: return CS6;
    case 7: return CS7;
    default: return CS8;
  }
}

void make_raw(termios& tio, const LineSettings& line) {
  cfmakeraw(&tio);
  tio.c_cflag &= ~static_cast<tcflag_t>(CSIZE | PARENB | PARODD | CSTOPB | CRTSCTS);
  tio.c_cflag |= size_flag(line.data_bits) | CLOCAL | CREAD;
  if (line.parity != Parity::kNone) {
    tio.c_cflag |= PARENB;
    if (line.parity == Parity::kOdd) tio.c_cflag |= PARODD;
    tio.c_iflag |= INPCK | IGNPAR;  // a character with a parity error is dropped
  }
  if (line.stop_bits == 2) tio.c_cflag |= CSTOPB;
  tio.c_cc[VMIN] = 1;
  tio.c_cc[VTIME] = 0;
}

bool format_kept(const termios& back, const LineSettings& line) {
  const bool parity = (back.c_cflag & PARENB) != 0;
  const bool odd = (back.c_cflag & PARODD) != 0;
  if (parity != (line.parity != Parity::kNone)) return false;
  if (parity && odd != (line.parity == Parity::kOdd)) return false;
  if ((back.c_cflag & CSIZE) != size_flag(line.data_bits)) return false;
  return ((back.c_cflag & CSTOPB) != 0) == (line.stop_bits == 2);
}

// Real adapter: throw. Pseudo-terminal: remember that it did not take everything (one note at
// the end, pty_note), and carry on.
void refuse(const SerialSetup& setup, bool& refused, LinkError e, const std::string& text) {
  if (!setup.is_pty) throw LinkException(e, text);
  refused = true;
}

// A pseudo-terminal carries bytes between two programs: it has no wire, so no parity bit and
// no bit rate, and Linux does not keep (or, on some kernels, refuses with EINVAL) what has no
// meaning there. That is no fault: one note, in words that do not read as an error.
void pty_note(SerialSetup& setup, bool refused, const std::string& name, const std::string& format,
              std::uint32_t baud, const LogFn& log) {
  if (!refused) return;
  const std::string note = name +
                           ": a pseudo-terminal has no wire, so no parity bit and no bit "
                           "rate: " +
                           format + " at " + std::to_string(baud) +
                           " bit/s is the two ends' agreement, not a setting; nothing to fix";
  setup.notes.push_back(note);
  if (log) log(note);
}

std::string format_text(const LineSettings& line) {
  const std::string full = to_string(line);
  return full.substr(full.find(' ') + 1);  // "8E1"
}

}  // namespace

bool mark_parity_errors(int fd) {
  termios tio{};
  if (tcgetattr(fd, &tio) != 0) return false;
  tio.c_iflag |= INPCK | PARMRK;
  tio.c_iflag &= ~static_cast<tcflag_t>(IGNPAR | ISTRIP);
  if (tcsetattr(fd, TCSANOW, &tio) != 0) return false;
  termios back{};
  if (tcgetattr(fd, &back) != 0) return false;
  if ((back.c_iflag & (INPCK | PARMRK | IGNPAR | ISTRIP)) != (INPCK | PARMRK)) {
    errno = EINVAL;
    return false;
  }
  return true;
}

bool is_pseudo_terminal(int fd) {
  struct stat st {};
  if (fstat(fd, &st) != 0 || !S_ISCHR(st.st_mode)) return false;
  const unsigned maj = major(st.st_rdev);
  const unsigned min = minor(st.st_rdev);
  // Unix98 pty slaves: majors 136..143; /dev/ptmx (5,2); legacy BSD ptys: 2 and 3.
  return (maj >= 136 && maj <= 143) || (maj == 5 && min == 2) || maj == 2 || maj == 3;
}

SerialSetup configure_serial(int fd, const LineSettings& line, const std::string& name,
                             const LogFn& log) {
  SerialSetup setup;
  setup.is_pty = is_pseudo_terminal(fd);
  termios tio{};
  if (tcgetattr(fd, &tio) != 0) {
    throw LinkException(LinkError::kNotATerminal, name + ": " + std::strerror(errno));
  }
  make_raw(tio, line);
  const auto speed = standard_speed(line.baud);
  if (speed) cfsetspeed(&tio, *speed);
  const std::string format = format_text(line);
  bool refused = false;  // a pty did not take everything
  if (tcsetattr(fd, TCSANOW, &tio) != 0) {
    refuse(setup, refused, LinkError::kAdapterRefusedFormat,
           name + ": tcsetattr " + format + " failed: " + std::strerror(errno));
  }
  if (!speed) {
    if (const int err = detail::set_custom_baud(fd, line.baud); err != 0) {
      refuse(
          setup, refused, LinkError::kAdapterRefusedBaudRate,
          name + ": " + std::to_string(line.baud) + " bit/s not accepted: " + std::strerror(err));
    }
  }
  termios back{};
  if (tcgetattr(fd, &back) != 0) {
    throw LinkException(LinkError::kNotATerminal, name + ": " + std::strerror(errno));
  }
  if (!format_kept(back, line)) {
    refuse(setup, refused, LinkError::kAdapterRefusedFormat, name + ": " + format + " not kept");
  }
  const std::uint32_t actual = detail::read_baud(fd);
  setup.actual_baud = actual;
  const double deviation = rate_deviation(line.baud, actual);
  if (actual != line.baud && !setup.is_pty && actual != 0 && std::abs(deviation) <= 0.02) {
    char percent[32];
    std::snprintf(percent, sizeof percent, "%+.2f %%", deviation * 100);
    const std::string warning = "warning: " + name + ": asked for " + std::to_string(line.baud) +
                                " bit/s, the adapter makes " + std::to_string(actual) + " bit/s (" +
                                percent + "; PROFIBUS allows ±0.3 %" +
                                (std::abs(deviation) > 0.003 ? ": expect character errors" : "") +
                                "); an adapter with an exact divisor (FTDI, CH341) avoids this";
    setup.notes.push_back(warning);
    if (log) log(warning);
  } else if (actual != line.baud) {
    refuse(setup, refused, LinkError::kAdapterRefusedBaudRate,
           name + ": asked for " + std::to_string(line.baud) + " bit/s, driver reports " +
               std::to_string(actual) + " bit/s");
  }
  pty_note(setup, refused, name, format, line.baud, log);
  return setup;
}

}  // namespace rs4sim::stream
