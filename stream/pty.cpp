#include "stream/pty.h"

#include "stream/link_error.h"

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace rs4sim::stream {

namespace {
[[noreturn]] void fail(const char* step) {
  throw LinkException(LinkError::kPtyFailed, std::string(step) + ": " + std::strerror(errno));
}

void make_raw(int fd) {
  termios tio{};
  if (tcgetattr(fd, &tio) != 0) fail("tcgetattr(pty)");
  cfmakeraw(&tio);
  if (tcsetattr(fd, TCSANOW, &tio) != 0) fail("tcsetattr(pty)");
}
}  // namespace

PseudoTerminal::PseudoTerminal() {
  master_fd_ = posix_openpt(O_RDWR | O_NOCTTY);
  if (master_fd_ < 0) fail("posix_openpt");
  try {
    if (grantpt(master_fd_) != 0) fail("grantpt");
    if (unlockpt(master_fd_) != 0) fail("unlockpt");
    char name[128] = {};
    if (ptsname_r(master_fd_, name, sizeof name) != 0) fail("ptsname");
    slave_path_ = name;
    slave_fd_ = ::open(name, O_RDWR | O_NOCTTY);
    if (slave_fd_ < 0) fail("open(pty slave)");
    make_raw(slave_fd_);
  } catch (...) {
    if (slave_fd_ >= 0) ::close(slave_fd_);
    ::close(master_fd_);
    throw;
  }
}

PseudoTerminal::~PseudoTerminal() {
  if (slave_fd_ >= 0) ::close(slave_fd_);
  if (master_fd_ >= 0) ::close(master_fd_);
}

int PseudoTerminal::release_master() {
  const int fd = master_fd_;
  master_fd_ = -1;
  return fd;
}

}  // namespace rs4sim::stream
