#pragma once
// The memory benchmarks' one measure: heap bytes in use (glibc); the difference around a
// construction is its heap share.

#include <benchmark/benchmark.h>

#include <malloc.h>

#include <cstddef>
#include <vector>

namespace rs4sim::bench {

inline std::size_t heap_in_use() { return mallinfo2().uordblks; }

// Heap bytes per object of state.range(0) objects made by `make(i)` (each a unique_ptr, all
// alive together), measured around their construction in every iteration; with
// `array_excluded` the vector that holds them is reserved before the first measure.
template <class Make>
double heap_per_object(benchmark::State& state, Make make, bool array_excluded = false) {
  const auto n = static_cast<std::size_t>(state.range(0));
  double per_object = 0;
  for (auto _ : state) {
    std::size_t before = heap_in_use();
    std::vector<decltype(make(std::size_t{0}))> objects;
    if (array_excluded) {
      objects.reserve(n);
      before = heap_in_use();
    }
    for (std::size_t i = 0; i < n; ++i) objects.push_back(make(i));
    per_object = static_cast<double>(heap_in_use() - before) / static_cast<double>(n);
    benchmark::DoNotOptimize(objects.data());
  }
  return per_object;
}

// The memory benchmarks' counters of a device type: its size, and its heap share per device
// (`heap_per_device`, the object itself included) as heap_per_object measured it.
template <class Device>
void count_device_memory(benchmark::State& state, double heap_per_device) {
  state.counters["sizeof_Device_B"] = static_cast<double>(sizeof(Device));
  state.counters["heap_per_device_B"] = heap_per_device;
}

}  // namespace rs4sim::bench
