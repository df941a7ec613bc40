#pragma once
// A pseudo-terminal pair for `rs4sim run --link pty` and for tests: the simulator keeps
// the master side; the external program (a DP master, a Modbus client, a script) opens
// slave_path() like a serial port.
//
// The slave side is put into raw mode and kept open by this object as well, so that the
// master side never sees EIO/hang-up while the external program reconnects.

#include <string>

namespace rs4sim::stream {

class PseudoTerminal {
 public:
  // posix_openpt + grantpt + unlockpt + ptsname; throws LinkException(kPtyFailed).
  PseudoTerminal();
  ~PseudoTerminal();
  PseudoTerminal(const PseudoTerminal&) = delete;
  PseudoTerminal& operator=(const PseudoTerminal&) = delete;

  [[nodiscard]] int master_fd() const { return master_fd_; }
  // Hands the master fd over (e.g. to an asio::serial_port); this object no longer closes it.
  [[nodiscard]] int release_master();
  [[nodiscard]] const std::string& slave_path() const { return slave_path_; }

 private:
  int master_fd_ = -1;
  int slave_fd_ = -1;
  std::string slave_path_;
};

}  // namespace rs4sim::stream
