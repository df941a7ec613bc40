#include "app/devices/rs4_state_file.h"

#include "app/runtime/whole_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace rs4sim::app {
namespace {

std::runtime_error refused(const std::string& path, const std::string& why) {
  return std::runtime_error("state file " + path + ": " + why + " (the file is left as it is)");
}

// Writes `bytes` to `path` through a temporary file in the same directory: write, fsync,
// rename, fsync the directory. Empty on success, else why not.
std::string write_atomically(const std::string& path, const std::vector<std::uint8_t>& bytes) {
  const std::string temporary = path + ".tmp";
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return temporary + ": " + std::strerror(errno);
  std::size_t done = 0;
  while (done < bytes.size()) {
    const auto n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string why = std::strerror(errno);
      ::close(fd);
      ::unlink(temporary.c_str());
      return temporary + ": " + why;
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(temporary.c_str());
    return temporary + ": " + why;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(temporary.c_str());
    return why;
  }
  const auto dir = std::filesystem::path(path).parent_path();
  const int dfd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {
    (void)::fsync(dfd);
    ::close(dfd);
  }
  return {};
}

}  // namespace

Rs4StateFile::Rs4StateFile(std::string path) : path_(std::move(path)) {
  std::error_code ec;
  if (!std::filesystem::exists(path_, ec)) {
    if (ec) throw refused(path_, ec.message());
    return;  // a new unit: the file is made at the first write
  }
  const auto file = read_whole_file(path_);
  if (!file) throw refused(path_, file.error);
  const std::vector<std::uint8_t> bytes(file.bytes.begin(), file.bytes.end());
  auto state = rs4::device::decode_state(bytes);
  if (!state) throw refused(path_, state.error().message());
  loaded_ = std::move(state).value();
}

void Rs4StateFile::keep(const rs4::device::Rs4Device& device) {
  const auto mark = rs4::device::state_mark(device);
  if (written_ && *written_ == mark) return;
  if (failed_ && *failed_ == mark) return;  // tried again at the next change
  if (!written_ && loaded_ && capture_state(device) == *loaded_) {
    written_ = mark;  // the memory as loaded: nothing to write
    return;
  }
  if (write(device)) {
    written_ = mark;
    failed_.reset();
  } else {
    failed_ = mark;
  }
}

bool Rs4StateFile::write(const rs4::device::Rs4Device& device) {
  const auto why = write_atomically(path_, rs4::device::encode_state(capture_state(device)));
  if (why.empty()) {
    if (failed_) std::cerr << "rs4sim: state file " << path_ << ": written again" << std::endl;
    return true;
  }
  std::cerr << "rs4sim: state file " << path_ << ": cannot write: " << why
            << " (tried again at the next change)" << std::endl;
  return false;
}

}  // namespace rs4sim::app
