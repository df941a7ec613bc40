#pragma once
// The two METRON fuzz targets' driver: a Device on a manual clock, on_time() at every
// deadline up to a target, each transmitted frame handed to a check with its time.

#include "metron/device.h"
#include "stream/clock.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace rs4sim::metron::fuzzing {

class Harness {
 public:
  using Check = std::function<void(const std::vector<std::uint8_t>&, stream::TimePoint)>;

  Harness(const Options& options, Check check) : device_(options), check_(std::move(check)) {
    advance(stream::Duration{});
  }

  Device& device() { return device_; }
  [[nodiscard]] stream::TimePoint now() const { return clock_.now(); }

  void drain() {
    while (auto f = device_.take_transmit()) check_(*f, clock_.now());
  }
  void send(std::span<const std::uint8_t> bytes) {
    device_.on_bytes(bytes, clock_.now());
    drain();
  }
  void advance(stream::Duration d) {
    const auto target = clock_.now() + d;
    for (int guard = 0; guard < 100000; ++guard) {
      const auto dl = device_.next_deadline();
      if (!dl || *dl > target) break;
      if (*dl > clock_.now()) clock_.set(*dl);
      device_.on_time(clock_.now());
      drain();
    }
    clock_.set(target);
  }

 private:
  stream::ManualClock clock_;
  Device device_;
  Check check_;
};

// Ops 0 (advance `arg` ms) and 1 (`arg` bytes to the device) shared by both scripts;
// false when `op` is another one.
inline bool common_op(Harness& h, std::uint8_t op, const std::uint8_t*& p,
                      const std::uint8_t* end) {
  const std::uint8_t arg = p < end ? *p++ : 0;
  if (op == 0) {
    h.advance(std::chrono::milliseconds(arg));
    return true;
  }
  if (op == 1) {
    const std::size_t n = std::min<std::size_t>(arg, static_cast<std::size_t>(end - p));
    h.send(std::span<const std::uint8_t>(p, n));
    p += n;
    return true;
  }
  --p;  // not ours: the argument byte stays for the caller
  return false;
}

}  // namespace rs4sim::metron::fuzzing
