#include "app/runtime/whole_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace rs4sim::app {

WholeFile read_whole_file(const std::string& path) {
  // std::ifstream opens a directory without complaint on Linux and then reads nothing: ask
  // first, so a directory is named as one instead of reading as an empty file.
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return {{}, std::strerror(EISDIR)};
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) return {{}, errno != 0 ? std::strerror(errno) : "cannot be opened"};
  std::ostringstream text;
  text << in.rdbuf();  // an empty file sets failbit on `text` only, which is not an error
  if (in.bad()) return {{}, errno != 0 ? std::strerror(errno) : std::strerror(EIO)};
  return {std::move(text).str(), {}};
}

}  // namespace rs4sim::app
