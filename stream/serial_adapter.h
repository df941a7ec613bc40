#pragma once
// The adapter behind a serial port, set up for a PROFIBUS line (docs/serial.md):
//   * low latency: a USB adapter hands received bytes to the host only when its latency timer
//     runs out (FTDI: 16 ms by default), longer than most slot times. The sysfs
//     `bus/usb-serial/devices/<tty>/latency_timer` is set to 1 ms where it exists, and
//     TIOCSSERIAL ASYNC_LOW_LATENCY is asked for (which ftdi_sio also maps to 1 ms); a note
//     says when neither took;
//   * RS-485 mode (TIOCSRS485, RTS on send) only where the driver has it: ENOTTY means it
//     has not (USB adapters switch direction themselves) and is not mentioned, any other
//     error is a note;
//   * the driver's name, from sysfs (`class/tty/<tty>/device/driver`), for the notes and
//     `rs4sim serial-check`.
// The sysfs root is a parameter so that the tests can point it at a directory of their own.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rs4sim::stream {

struct AdapterSetup {
  std::string tty;                      // "ttyUSB0"
  std::string driver;                   // "ftdi_sio", "cp210x", "ch341-uart"; empty: unknown
  std::optional<int> latency_timer_ms;  // as read back after setting it; nullopt: no such file
  bool async_low_latency = false;       // TIOCSSERIAL ASYNC_LOW_LATENCY took
  bool rs485 = false;                   // RS-485 mode on (TIOCSRS485)
  std::vector<std::string> notes;       // what could not be set (already passed to the log)
  [[nodiscard]] bool low_latency() const {
    return async_low_latency || (latency_timer_ms && *latency_timer_ms <= 1);
  }
};

// The tty name of an open descriptor ("ttyUSB0", "pts/3"), from /proc/self/fd; empty if unknown.
[[nodiscard]] std::string tty_name(int fd);

// The driver of `tty` from sysfs; empty when sysfs does not say.
[[nodiscard]] std::string adapter_driver(const std::string& tty, const std::string& sysfs_root);

// Reads the adapter's settings without changing them (`rs4sim serial-check`): driver, latency
// timer, ASYNC_LOW_LATENCY flag, RS-485 mode.
[[nodiscard]] AdapterSetup read_adapter(int fd, const std::string& tty,
                                        const std::string& sysfs_root = "/sys");

// Sets low latency and RS-485 mode as above; never throws. `log` gets every note.
AdapterSetup tune_adapter(int fd, const std::string& tty,
                          const std::function<void(const std::string&)>& log,
                          const std::string& sysfs_root = "/sys");

// The PROFIBUS rate check: `asked` against what the driver reports it set, `actual`
// (termios2 readback). A UART tolerates a few per cent between the two ends of a line; the
// PROFIBUS rate tolerance is ±0.3 % [IEC 61158-2 baud rate tolerance]. Returns the relative
// deviation (actual - asked) / asked.
[[nodiscard]] double rate_deviation(std::uint32_t asked, std::uint32_t actual);

}  // namespace rs4sim::stream
