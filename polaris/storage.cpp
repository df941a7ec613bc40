#include "polaris/storage.h"

#include <algorithm>

namespace rs4sim::polaris {

std::uint16_t stored_size(DataStorage storage, std::span<const std::uint8_t> interrupted) noexcept {
  if (storage == DataStorage::kNone) return 0;
  const bool object = storage == DataStorage::kObject;
  std::size_t best = 0;
  std::size_t run = 0;
  bool seen_interrupted = false;  // a hole needs an interrupted beam on both sides
  for (const std::uint8_t b : interrupted) {
    const bool hit = b != 0;
    if (object ? hit : !hit) {
      ++run;
      if (object) best = std::max(best, run);
      continue;
    }
    if (!object && seen_interrupted) best = std::max(best, run);
    seen_interrupted = seen_interrupted || hit;
    run = 0;
  }
  return static_cast<std::uint16_t>(best);
}

void Storage::observe(DataStorage storage, std::span<const std::uint8_t> interrupted) {
  const std::uint16_t size = stored_size(storage, interrupted);
  if (size <= size_) return;
  stored_.assign(interrupted.begin(), interrupted.end());
  size_ = size;
}

void Storage::transmitted(const Options& o, std::span<const std::uint8_t> in_view) {
  if (o.storage_mode != StorageMode::kTemporary) return;
  clear();
  observe(o.storage, in_view);
}

std::span<const std::uint8_t> Storage::scan(const Options& o,
                                            std::span<const std::uint8_t> in_view) const {
  if (o.storage == DataStorage::kNone || size_ == 0) return in_view;
  return stored_;
}

void Storage::clear() {
  stored_.clear();
  size_ = 0;
}

}  // namespace rs4sim::polaris
