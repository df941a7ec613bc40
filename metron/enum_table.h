// Enumerations whose values number the entries of a table in the enumeration's order (the
// names of the options and of the wire file's keys, the wire table's codes).
#pragma once

#include <array>
#include <cstddef>
#include <optional>

namespace rs4sim::metron {

// The value whose entry in `table` is `entry`; none when no entry is.
template <class E, class T, std::size_t N, class U>
[[nodiscard]] std::optional<E> enum_of_entry(const std::array<T, N>& table, const U& entry) {
  for (std::size_t i = 0; i < N; ++i)
    if (table[i] == entry) return static_cast<E>(i);
  return std::nullopt;
}

}  // namespace rs4sim::metron
