#pragma once
// The barrier's data storage [Polaris manual §7.4.2]: "Data storage: None: No storage.
// Object: Store the position and maximum length of objects. Hole: Store the position and
// maximum diameter of holes." and "Storage mode: Temporary: reset the storage memory after
// each data transmission. Permanent: permanent storage of the last interrupted beam."
//
// The manual gives no more; the model ([docs/decisions.md#polaris-data-storage]): the memory
// holds the scan whose longest object (Object) or widest hole (Hole) is the largest seen;
// the data block is made from that scan instead of the one in view. Temporary empties it
// after each data transmission (an answer to a data read, a master's push), after which it
// holds the scan then in view; Permanent never empties it, so an object that has left is
// still transmitted until a larger one replaces it.

#include "polaris/options.h"

#include <cstdint>
#include <span>
#include <vector>

namespace rs4sim::polaris {

// The longest run of interrupted beams (Object) or of free beams between two interrupted
// ones (Hole), in beams; 0 with None or when there is none.
[[nodiscard]] std::uint16_t stored_size(DataStorage storage,
                                        std::span<const std::uint8_t> interrupted) noexcept;

class Storage {
 public:
  // A scan saw `interrupted` (per physical beam, as Scene::flags()): kept when its size is
  // larger than the stored scan's.
  void observe(DataStorage storage, std::span<const std::uint8_t> interrupted);
  // A data transmission left while `in_view` is seen: Temporary empties the memory, which
  // then holds `in_view` (if it has an object or hole).
  void transmitted(const Options& o, std::span<const std::uint8_t> in_view);
  // What the data block is made from: the stored scan, or `in_view` when nothing is stored
  // (or with None).
  [[nodiscard]] std::span<const std::uint8_t> scan(const Options& o,
                                                   std::span<const std::uint8_t> in_view) const;
  // The stored scan's size (stored_size); 0 when empty.
  [[nodiscard]] std::uint16_t size() const { return size_; }
  void clear();

 private:
  std::vector<std::uint8_t> stored_;
  std::uint16_t size_ = 0;
};

}  // namespace rs4sim::polaris
