#pragma once
// What the barrier measures in one scan, from the scene (which beams are interrupted), in
// each data mode [Polaris manual §7.4.3, §8.2]. The scene counts beams physically, 1 next
// to the connector cap; the scan direction decides the transmitted numbering (reverse:
// beam 1 at the far cap). Beam numbers start at 1; 0 means "no object".

#include "polaris/options.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rs4sim::polaris {

// A run of adjacent interrupted beams; `last` is the last interrupted beam, inclusive (the
// manual's examples; its text says "first free beam").
struct Object {
  std::uint16_t first = 0;
  std::uint16_t last = 0;
  friend bool operator==(const Object&, const Object&) = default;
};

// `interrupted[i]` (non-zero) is physical beam i+1. Objects in transmitted numbering, ascending.
[[nodiscard]] std::vector<Object> find_objects(const Options& o,
                                               std::span<const std::uint8_t> interrupted);

// The words of the mode's data block: 485MB ceil(N/16) words, 1 = beam free, padded with
// 1s (bit order per Options); FL1/FL4/FL10 the first 1/4/10 objects counted from beam 1
// (DECISION), unused pairs 0000 0000, then the overall (first, last).
[[nodiscard]] std::vector<std::uint16_t> data_words(const Options& o,
                                                    std::span<const std::uint8_t> interrupted);

// Words of the data block: ceil(N/16), 2, 10 or 22.
[[nodiscard]] std::size_t block_words(const Options& o) noexcept;

}  // namespace rs4sim::polaris
