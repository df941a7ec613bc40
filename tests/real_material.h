#pragma once
// Real material nobody on the project wrote (vendor GSD files, bytes read off real PROFIBUS
// lines) is never copied into the repository: tests read it at run time from `shared/real`
// beside the repository root (in its parent folder), or from the directory $RS4SIM_REAL_DIR names,
// and skip with a message when it is absent (a user's own clone). Facts derived by hand from
// those files (an ident, a count) are written into the tests; the files' bytes are not.
//
// The test target passes its source root: rs4sim_test_paths(TARGET RS4SIM_SOURCE_DIR ...)
// (tests/CMakeLists.txt).

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string_view>

namespace rs4sim::testing {

inline std::filesystem::path real_material_dir() {
  if (const char* env = std::getenv("RS4SIM_REAL_DIR"); env != nullptr && *env != '\0') {
    return env;
  }
  return std::filesystem::path(RS4SIM_SOURCE_DIR).parent_path() / "shared" / "real";
}

// `relative` under the real material, when that file exists.
inline std::optional<std::filesystem::path> real_file(std::string_view relative) {
  auto path = real_material_dir() / relative;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  return path;
}

}  // namespace rs4sim::testing
