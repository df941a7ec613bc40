#pragma once
// The real PROFIsafe V2 capture nobody on the project wrote is never copied into the repository:
// the tests read it at run time from `shared/profisafe` beside the repository root (in its parent
// folder), or from the directory $RS4SIM_PROFISAFE_DIR names, and skip with a message when it is
// absent (a user's own clone). Facts derived by hand from it (counts, CRC1, offsets) are written
// into the tests. The test target passes its source root (RS4SIM_SOURCE_DIR).

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string_view>

namespace rs4sim::testing {

inline constexpr std::string_view kProfisafeV2Capture = "seb711_krc4_profisafe_v2_status.pcap";

inline std::optional<std::filesystem::path> profisafe_capture() {
  std::filesystem::path dir;
  if (const char* env = std::getenv("RS4SIM_PROFISAFE_DIR"); env != nullptr && *env != '\0') {
    dir = env;
  } else {
    dir = std::filesystem::path(RS4SIM_SOURCE_DIR).parent_path() / "shared" / "profisafe";
  }
  auto path = dir / kProfisafeV2Capture;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  return path;
}

}  // namespace rs4sim::testing
