#include "stream/serial_adapter.h"

#include <linux/serial.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace rs4sim::stream {

namespace fs = std::filesystem;

std::string tty_name(int fd) {
  std::error_code ec;
  const fs::path target = fs::read_symlink("/proc/self/fd/" + std::to_string(fd), ec);
  if (ec) return {};
  const std::string s = target.string();
  if (s.rfind("/dev/", 0) != 0) return {};
  return s.substr(5);  // "ttyUSB0", "pts/3"
}

std::string adapter_driver(const std::string& tty, const std::string& sysfs_root) {
  std::error_code ec;
  const fs::path link =
      fs::read_symlink(fs::path(sysfs_root) / "class/tty" / tty / "device/driver", ec);
  return ec ? std::string() : link.filename().string();
}

namespace {

constexpr int kLowLatency = static_cast<int>(ASYNC_LOW_LATENCY);

fs::path latency_file(const std::string& tty, const std::string& sysfs_root) {
  return fs::path(sysfs_root) / "bus/usb-serial/devices" / tty / "latency_timer";
}

std::optional<int> read_latency(const fs::path& file) {
  std::ifstream in(file);
  int ms = -1;
  if (!(in >> ms) || ms < 0) return std::nullopt;
  return ms;
}

bool rs485_enabled(int fd) {
  serial_rs485 rs{};
  return ::ioctl(fd, TIOCGRS485, &rs) == 0 && (rs.flags & SER_RS485_ENABLED) != 0;
}

}  // namespace

AdapterSetup read_adapter(int fd, const std::string& tty, const std::string& sysfs_root) {
  AdapterSetup a;
  a.tty = tty;
  a.driver = adapter_driver(tty, sysfs_root);
  a.latency_timer_ms = read_latency(latency_file(tty, sysfs_root));
  serial_struct ss{};
  a.async_low_latency = ::ioctl(fd, TIOCGSERIAL, &ss) == 0 && (ss.flags & kLowLatency) != 0;
  a.rs485 = rs485_enabled(fd);
  return a;
}

AdapterSetup tune_adapter(int fd, const std::string& tty,
                          const std::function<void(const std::string&)>& log,
                          const std::string& sysfs_root) {
  AdapterSetup a;
  a.tty = tty;
  a.driver = adapter_driver(tty, sysfs_root);
  const std::string who = "/dev/" + tty + (a.driver.empty() ? "" : " (" + a.driver + ")");
  const auto note = [&](const std::string& text) {
    a.notes.push_back(who + ": " + text);
    if (log) log(a.notes.back());
  };
  // 1. The USB adapter's latency timer in sysfs.
  std::string why_not;
  const fs::path file = latency_file(tty, sysfs_root);
  std::error_code ec;
  if (fs::exists(file, ec)) {
    a.latency_timer_ms = read_latency(file);
    if (!a.latency_timer_ms || *a.latency_timer_ms > 1) {
      std::ofstream out(file);
      out << "1\n";
      out.flush();
      if (!out) why_not = "writing 1 to " + file.string() + " failed: " + std::strerror(errno);
      a.latency_timer_ms = read_latency(file);
    }
  }
  // 2. ASYNC_LOW_LATENCY (8250 UARTs; ftdi_sio maps it to a 1 ms latency timer).
  serial_struct ss{};
  if (::ioctl(fd, TIOCGSERIAL, &ss) != 0) {
    const int err = errno;
    if (why_not.empty()) why_not = std::string("TIOCGSERIAL: ") + std::strerror(err);
  } else if ((ss.flags & kLowLatency) != 0) {
    a.async_low_latency = true;
  } else {
    ss.flags |= kLowLatency;
    if (::ioctl(fd, TIOCSSERIAL, &ss) == 0) {
      a.async_low_latency = true;
    } else if (why_not.empty()) {
      why_not = std::string("TIOCSSERIAL ASYNC_LOW_LATENCY: ") + std::strerror(errno);
    }
  }
  if (!a.low_latency()) {
    note("low-latency mode not set (" + (why_not.empty() ? "no way to set it" : why_not) +
         (a.latency_timer_ms ? "; latency timer " + std::to_string(*a.latency_timer_ms) + " ms"
                             : "") +
         "): replies may come late for the master's slot time");
  }
  // 3. RS-485 mode where the driver has it.
  serial_rs485 rs{};
  if (::ioctl(fd, TIOCGRS485, &rs) != 0) {
    const int err = errno;
    if (err != ENOTTY) note(std::string("TIOCGRS485: ") + std::strerror(err));
  } else if ((rs.flags & SER_RS485_ENABLED) != 0) {
    a.rs485 = true;  // set up already (device tree, a previous run): kept as it is
  } else {
    rs.flags |= SER_RS485_ENABLED | SER_RS485_RTS_ON_SEND;
    rs.flags &= ~static_cast<decltype(rs.flags)>(SER_RS485_RTS_AFTER_SEND);
    rs.delay_rts_before_send = 0;
    rs.delay_rts_after_send = 0;
    if (::ioctl(fd, TIOCSRS485, &rs) == 0) {
      a.rs485 = true;
    } else if (errno != ENOTTY) {
      note(std::string("TIOCSRS485: ") + std::strerror(errno));
    }
  }
  return a;
}

double rate_deviation(std::uint32_t asked, std::uint32_t actual) {
  if (asked == 0) return 0;
  return (static_cast<double>(actual) - static_cast<double>(asked)) / static_cast<double>(asked);
}

}  // namespace rs4sim::stream
