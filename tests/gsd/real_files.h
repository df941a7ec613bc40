#pragma once
// Where the tests find the project's real material (GSD files nobody on the project wrote): the
// folder `real/gsd` of the `shared` directory beside the repository root, or the folder the
// environment variable RS4SIM_REAL_DIR names (its `gsd` subfolder), e.g. for a worktree that is
// not beside it. Never copied into the repository.
#include "tests/real_material.h"

#include <filesystem>
#include <optional>
#include <string>

namespace rs4sim::gsd::testing {

inline std::filesystem::path real_root() { return rs4sim::testing::real_material_dir(); }

inline std::optional<std::filesystem::path> real_gsd_dir() {
  const auto dir = real_root() / "gsd";
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) return std::nullopt;
  return dir;
}

inline std::string real_gsd_skip_message() {
  return "no real GSD files at " + (real_root() / "gsd").string() +
         " (the project's real material is not beside this clone; set RS4SIM_REAL_DIR)";
}

}  // namespace rs4sim::gsd::testing
