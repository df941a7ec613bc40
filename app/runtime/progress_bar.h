#pragma once
// The progress bar of the console lines (rs4sim master, rs4sim demo):
// "[########------------]", 20 cells, one per 5 % done.

#include <algorithm>
#include <cstddef>
#include <string>

namespace rs4sim::app {

inline std::string progress_bar(std::size_t done, std::size_t total) {
  constexpr std::size_t kCells = 20;
  const std::size_t filled = total == 0 ? 0 : std::min(kCells, done * kCells / total);
  return "[" + std::string(filled, '#') + std::string(kCells - filled, '-') + "]";
}

}  // namespace rs4sim::app
