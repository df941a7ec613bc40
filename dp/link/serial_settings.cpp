#include "dp/link/serial_settings.h"

#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <termios.h>

#include <cerrno>
#include <cstring>

namespace rs4sim::dp::link {

namespace {

std::optional<speed_t> standard_speed(BaudRate b) {
  switch (b) {
    case BaudRate::k9k6: return B9600;
    case BaudRate::k19k2: return B19200;
    case BaudRate::k500k: return B500000;
    case BaudRate::k1M5: return B1500000;
    case BaudRate::k3M: return B3000000;
    default: return std::nullopt;  // 45.45k, 93.75k, 187.5k, 6M, 12M: termios2
  }
}

void raw_8e1(termios& tio) {
  cfmakeraw(&tio);
  tio.c_cflag &= ~static_cast<tcflag_t>(CSIZE | PARODD | CSTOPB | CRTSCTS);
  tio.c_cflag |= CS8 | PARENB | CLOCAL | CREAD;  // [IEC 61158-4-3 UART character]
                                                 // [IEC 61158-2 baud rates]: 8 data bits, even
                                                 // parity, 1 stop
  tio.c_iflag |= INPCK | IGNPAR;                 // a character with a parity error is dropped
                                  // ([IEC 61158-4-3 UART character] [IEC 61158-2 baud rates])
  tio.c_cc[VMIN] = 1;
  tio.c_cc[VTIME] = 0;
}

// Real adapter: throw. Pseudo-terminal: note and carry on.
void refuse(SerialSetup& setup, LinkError e, const std::string& text, const LogFn& log) {
  if (!setup.is_pty) throw LinkException(e, text);
  const std::string note = text + " (pseudo-terminal: no physical line, carrying on)";
  setup.notes.push_back(note);
  if (log) log(note);
}

}  // namespace

bool is_pseudo_terminal(int fd) {
  struct stat st {};
  if (fstat(fd, &st) != 0 || !S_ISCHR(st.st_mode)) return false;
  const unsigned maj = major(st.st_rdev);
  const unsigned min = minor(st.st_rdev);
  // Unix98 pty slaves: majors 136..143; /dev/ptmx (5,2); legacy BSD ptys: 2 and 3.
  return (maj >= 136 && maj <= 143) || (maj == 5 && min == 2) || maj == 2 || maj == 3;
}

SerialSetup configure_serial(int fd, BaudRate baud, const std::string& name, const LogFn& log) {
  SerialSetup setup;
  setup.is_pty = is_pseudo_terminal(fd);
  termios tio{};
  if (tcgetattr(fd, &tio) != 0) {
    throw LinkException(LinkError::kNotATerminal, name + ": " + std::strerror(errno));
  }
  raw_8e1(tio);
  const auto speed = standard_speed(baud);
  if (speed) cfsetspeed(&tio, *speed);
  if (tcsetattr(fd, TCSANOW, &tio) != 0) {
    refuse(setup, LinkError::kAdapterRefusedFormat,
           name + ": tcsetattr 8E1 failed: " + std::strerror(errno), log);
  }
  if (!speed) {
    if (const int err = detail::set_custom_baud(fd, bits_per_second(baud)); err != 0) {
      refuse(setup, LinkError::kAdapterRefusedBaudRate,
             name + ": " + to_string(baud) + " baud not accepted: " + std::strerror(err), log);
    }
  }
  termios back{};
  if (tcgetattr(fd, &back) != 0) {
    throw LinkException(LinkError::kNotATerminal, name + ": " + std::strerror(errno));
  }
  if ((back.c_cflag & PARENB) == 0 || (back.c_cflag & PARODD) != 0 ||
      (back.c_cflag & CSIZE) != CS8) {
    refuse(setup, LinkError::kAdapterRefusedFormat, name + ": even parity / 8 data bits not kept",
           log);
  }
  const std::uint32_t actual = detail::read_baud(fd);
  if (actual != bits_per_second(baud)) {
    refuse(setup, LinkError::kAdapterRefusedBaudRate,
           name + ": asked for " + to_string(baud) + " baud, driver reports " +
               std::to_string(actual) + " bit/s",
           log);
  }
  return setup;
}

}  // namespace rs4sim::dp::link
