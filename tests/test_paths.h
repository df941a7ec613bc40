// The paths a test reads (its data in the source tree, a program of the build tree), handed
// in by CMake relative to the test executable's folder (rs4sim_test_paths in
// tests/CMakeLists.txt) and made absolute here, at run time. A path relative to the
// executable works whatever the current folder; an absolute path in a compiler flag would
// tie every object to one clone and defeat the compiler cache (docs/ci.md).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace rs4sim::testing {

// The folder of the running executable ([proc(5)] /proc/self/exe) joined with `relative`.
inline std::string from_test_dir(std::string_view relative) {
  static const std::filesystem::path folder =
      std::filesystem::read_symlink("/proc/self/exe").parent_path();
  auto path = (folder / relative).lexically_normal();
  // "a/b/.." normalises to "a/": without the trailing separator, parent_path() is the parent.
  if (!path.has_filename() && path.has_relative_path()) path = path.parent_path();
  return path.string();
}

}  // namespace rs4sim::testing
