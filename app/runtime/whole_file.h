// Reading a whole file the user named (a GSD, a bus file, a wire table, a token, a parameter
// set, an archive export): one place that tells a directory, a missing file, a permission
// problem and a read error apart, so every option that takes a file gives the same precise
// reason, in the operating system's words.
#pragma once

#include <string>

namespace rs4sim::app {

struct WholeFile {
  std::string bytes;  // the file's content, as it is (binary-safe)
  // Empty when the file was read; otherwise why not, as strerror() words it: "No such file or
  // directory", "Permission denied", "Is a directory", "Input/output error".
  std::string error;

  explicit operator bool() const { return error.empty(); }
};

WholeFile read_whole_file(const std::string& path);

}  // namespace rs4sim::app
