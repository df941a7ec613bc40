// Linux termios2 (arbitrary baud rates via BOTHER). Kept apart: <asm/termbits.h> clashes
// with <termios.h>, which the rest of the link code uses.
#include <asm/ioctls.h>
#include <asm/termbits.h>

#include <cerrno>
#include <cstdint>

extern "C" int ioctl(int fd, unsigned long request, ...) noexcept;

namespace rs4sim::stream::detail {

int set_custom_baud(int fd, std::uint32_t bps) {
  struct termios2 tio {};
  if (ioctl(fd, TCGETS2, &tio) != 0) return errno;
  tio.c_cflag &= ~static_cast<tcflag_t>(CBAUD | (CBAUD << IBSHIFT));
  tio.c_cflag |= BOTHER | (BOTHER << IBSHIFT);
  tio.c_ispeed = bps;
  tio.c_ospeed = bps;
  if (ioctl(fd, TCSETS2, &tio) != 0) return errno;
  return 0;
}

std::uint32_t read_baud(int fd) {
  struct termios2 tio {};
  if (ioctl(fd, TCGETS2, &tio) != 0) return 0;
  return tio.c_ospeed;
}

}  // namespace rs4sim::stream::detail
