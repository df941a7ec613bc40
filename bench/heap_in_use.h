#pragma once
// The memory benchmarks' one measure: heap bytes in use (glibc); the difference around a
// construction is its heap share.

#include <malloc.h>

#include <cstddef>

namespace rs4sim::bench {

inline std::size_t heap_in_use() { return mallinfo2().uordblks; }

}  // namespace rs4sim::bench
