#include "polaris/scene.h"

#include <algorithm>

namespace rs4sim::polaris {

std::string_view to_string(SceneError e) noexcept {
  switch (e) {
    case SceneError::kNoSuchBeam: return "no such beam";
  }
  return "unknown scene error";
}

std::error_code Scene::set_interrupted(std::span<const std::uint16_t> beams) {
  for (const std::uint16_t b : beams) {
    if (b == 0 || b > interrupted_.size()) {
      return SceneError::kNoSuchBeam;
    }
  }
  std::fill(interrupted_.begin(), interrupted_.end(), std::uint8_t{0});
  for (const std::uint16_t b : beams) interrupted_[b - 1U] = 1;
  return {};
}

std::vector<std::uint16_t> Scene::interrupted() const {
  std::vector<std::uint16_t> beams;
  for (std::size_t i = 0; i < interrupted_.size(); ++i) {
    if (interrupted_[i] != 0) beams.push_back(static_cast<std::uint16_t>(i + 1U));
  }
  return beams;
}

bool Scene::any_interrupted() const {
  return std::any_of(interrupted_.begin(), interrupted_.end(),
                     [](std::uint8_t b) { return b != 0; });
}

}  // namespace rs4sim::polaris
