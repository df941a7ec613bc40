#include "stream/serial_transport.h"

#include <boost/asio/error.hpp>
#include <boost/asio/write.hpp>

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace rs4sim::stream {

namespace asio = boost::asio;

namespace {
int open_device(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw LinkException(LinkError::kOpenFailed, path + ": " + std::strerror(errno));
  return fd;
}
}  // namespace

SerialTransport::SerialTransport(asio::io_context& io, const std::string& path,
                                 const LineSettings& line, const LogFn& log)
    : SerialTransport(io, open_device(path), line, path, log) {}

SerialTransport::SerialTransport(asio::io_context& io, int fd, const LineSettings& line,
                                 const std::string& name, const LogFn& log)
    : port_(io), retry_timer_(io), parity_(line.parity != Parity::kNone), log_(log) {
  try {
    setup_ = configure_serial(fd, line, name, log);
    if (!setup_.is_pty) setup_.adapter = tune_adapter(fd, tty_name(fd), log);
  } catch (...) {
    ::close(fd);
    throw;
  }
  port_.assign(fd);
  // send() writes directly; a full buffer must give EAGAIN, not block the loop.
  const int flags = ::fcntl(fd, F_GETFL);
  if (flags >= 0) (void)::fcntl(fd, F_SETFL, flags | O_NONBLOCK);
}

SerialTransport::~SerialTransport() { close(); }

void SerialTransport::set_damaged_handler(DamagedFn on_damaged) {
  on_damaged_ = std::move(on_damaged);
  if (!on_damaged_ || !parity_ || setup_.is_pty || marks_ || !port_.is_open()) return;
  if (mark_parity_errors(port_.native_handle())) {
    marks_.emplace();
  } else if (log_) {
    log_(std::string("serial port refused PARMRK (") + std::strerror(errno) +
         "): characters with a parity error are dropped (IGNPAR)");
  }
}

void SerialTransport::start(BytesFn on_bytes, ErrorFn on_error) {
  on_bytes_ = std::move(on_bytes);
  on_error_ = std::move(on_error);
  read_next();
}

void SerialTransport::read_next() {
  port_.async_read_some(asio::buffer(rx_),
                        [this](const boost::system::error_code& ec, std::size_t n) {
                          if (ec == asio::error::operation_aborted || !port_.is_open()) return;
                          if (ec) {
                            // e.g. EIO while the other side of a pty is closed: report, retry
                            // shortly.
                            if (on_error_) on_error_(ec);
                            retry_timer_.expires_after(std::chrono::milliseconds(100));
                            retry_timer_.async_wait([this](const boost::system::error_code& e) {
                              if (!e && port_.is_open()) read_next();
                            });
                            return;
                          }
                          const std::span<const std::uint8_t> chunk(rx_.data(), n);
                          if (marks_) {
                            marks_->feed(
                                chunk,
                                [this](std::span<const std::uint8_t> good) {
                                  if (on_bytes_) on_bytes_(good);
                                },
                                [this](std::uint8_t damaged) {
                                  if (on_damaged_) on_damaged_(damaged);
                                });
                          } else if (on_bytes_) {
                            on_bytes_(chunk);
                          }
                          read_next();
                        });
}

void SerialTransport::send(std::span<const std::uint8_t> frame) {
  if (!port_.is_open()) return;
  ++writes_.frames;
  std::size_t written = 0;
  if (!writing_) {
    // The whole telegram in one write(): the UART then sends its characters back to back.
    const ssize_t n = ::write(port_.native_handle(), frame.data(), frame.size());
    if (n == static_cast<ssize_t>(frame.size())) {
      ++writes_.whole;
      return;
    }
    if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) {
      ++writes_.errors;
      if (on_error_) on_error_(std::error_code(errno, std::generic_category()));
      return;
    }
    written = n > 0 ? static_cast<std::size_t>(n) : 0;
  }
  ++writes_.split;  // the kernel's buffer is full: the rest follows when it drains
  tx_.emplace_back(frame.begin() + static_cast<std::ptrdiff_t>(written), frame.end());
  if (!writing_) write_next();
}

void SerialTransport::write_next() {
  if (tx_.empty()) {
    writing_ = false;
    return;
  }
  writing_ = true;
  asio::async_write(port_, asio::buffer(tx_.front()),
                    [this](const boost::system::error_code& ec, std::size_t) {
                      if (ec == asio::error::operation_aborted || tx_.empty()) return;
                      if (ec) {
                        ++writes_.errors;
                        if (on_error_) on_error_(ec);
                      }
                      tx_.pop_front();
                      write_next();
                    });
}

void SerialTransport::close() {
  retry_timer_.cancel();
  if (port_.is_open()) {
    boost::system::error_code ignored;
    port_.close(ignored);
  }
  tx_.clear();
  writing_ = false;
}

}  // namespace rs4sim::stream
