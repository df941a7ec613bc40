#include "metron/scene.h"

#include <algorithm>

namespace rs4sim::metron {

std::string_view to_string(SceneError e) noexcept {
  switch (e) {
    case SceneError::kNoSuchBeam: return "no such beam (beams are numbered 1..the beam count)";
  }
  return "unknown scene error";
}

std::error_code Scene::set_interrupted(std::span<const std::uint16_t> beams) {
  for (const auto b : beams)
    if (b < 1 || b > this->beams()) return SceneError::kNoSuchBeam;
  clear();
  for (const auto b : beams) interrupted_[b - 1U] = true;
  return {};
}

std::vector<std::uint16_t> Scene::interrupted() const {
  std::vector<std::uint16_t> out;
  for (std::size_t i = 0; i < interrupted_.size(); ++i)
    if (interrupted_[i]) out.push_back(static_cast<std::uint16_t>(i + 1U));
  return out;
}

void Scene::set_interrupted(std::uint16_t beam, bool interrupted) {
  if (beam >= 1 && beam <= beams()) interrupted_[beam - 1U] = interrupted;
}

void Scene::clear() { std::fill(interrupted_.begin(), interrupted_.end(), false); }

bool Scene::interrupted(std::uint16_t beam) const {
  return beam >= 1 && beam <= beams() && interrupted_[beam - 1U];
}

bool Scene::any_interrupted() const {
  return std::find(interrupted_.begin(), interrupted_.end(), true) != interrupted_.end();
}

std::uint8_t Scene::measure(Measurement m) const {
  unsigned first = 0, last = 0, count = 0, run = 0, longest = 0;
  for (unsigned i = 0; i < interrupted_.size(); ++i) {
    if (!interrupted_[i]) {
      run = 0;
      continue;
    }
    if (first == 0) first = i + 1;
    last = i + 1;
    ++count;
    longest = std::max(longest, ++run);
  }
  unsigned v = 0;
  switch (m) {
    case Measurement::kFirstInterrupted: v = first; break;
    case Measurement::kLastInterrupted: v = last; break;
    case Measurement::kInterruptedCount: v = count; break;
    case Measurement::kFreeCount: v = beams() - count; break;
    case Measurement::kCentralInterrupted: v = (first + last) / 2; break;
    case Measurement::kLongestRun: v = longest; break;
  }
  return static_cast<std::uint8_t>(std::min(v, 255U));
}

std::vector<std::uint8_t> Scene::packed(bool lsb_first) const {
  std::vector<std::uint8_t> out((interrupted_.size() + 7) / 8, 0);
  for (std::size_t i = 0; i < interrupted_.size(); ++i) {
    if (!interrupted_[i]) continue;
    const unsigned bit = lsb_first ? (i % 8) : 7 - (i % 8);
    out[i / 8] = static_cast<std::uint8_t>(out[i / 8] | (1U << bit));
  }
  return out;
}

}  // namespace rs4sim::metron
