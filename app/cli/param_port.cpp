#include "app/cli/param_port.h"

#include "app/cli/param_sources.h"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>

namespace rs4sim::app::param {
namespace {

[[noreturn]] void fail(const std::string& path, const char* step) {
  throw ParamCommandError(path + ": " + step + ": " + std::strerror(errno));
}

bool is_answer(const rs4::rs232::Answer& a) {
  return !std::holds_alternative<rs4::protocol::MeasurementTelegram>(a) &&
         !std::holds_alternative<rs4::protocol::WarningTelegram>(a);
}

}  // namespace

SerialPort::SerialPort(const std::string& path, std::chrono::milliseconds timeout)
    : timeout_(timeout) {
  fd_ = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
  if (fd_ < 0) fail(path, "open");
  termios tio{};
  if (::tcgetattr(fd_, &tio) != 0) {
    ::close(fd_);
    fail(path, "not a serial device");
  }
  ::cfmakeraw(&tio);
  ::cfsetspeed(&tio, B57600);  // the RS4's default, 8N1 ([docs/rs232.md])
  if (::tcsetattr(fd_, TCSANOW, &tio) != 0) {
    ::close(fd_);
    fail(path, "tcsetattr");
  }
  ::tcflush(fd_, TCIFLUSH);
}

SerialPort::~SerialPort() {
  if (fd_ >= 0) ::close(fd_);
}

std::optional<rs4::rs232::Answer> SerialPort::exchange(std::span<const std::uint8_t> frame) {
  std::size_t sent = 0;
  while (sent < frame.size()) {
    const auto n = ::write(fd_, frame.data() + sent, frame.size() - sent);
    if (n < 0 && errno != EAGAIN && errno != EINTR) return std::nullopt;
    if (n > 0) sent += static_cast<std::size_t>(n);
  }
  const auto deadline = std::chrono::steady_clock::now() + timeout_;
  std::array<std::uint8_t, 4096> buffer{};
  while (true) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return std::nullopt;
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(left.count())) <= 0) continue;
    const auto n = ::read(fd_, buffer.data(), buffer.size());
    if (n <= 0) continue;
    for (auto& answer : reader_.feed({buffer.data(), static_cast<std::size_t>(n)})) {
      if (answer && is_answer(answer.value())) return answer.value();
    }
  }
}

}  // namespace rs4sim::app::param
