#pragma once
// Injected time ([docs/design.md#injected-time]). Protocol cores never read a clock: they receive
// `now` and report their next deadline. Only the event loop (and tests) own a Clock.

#include <chrono>

namespace rs4sim::stream {

using SteadyClock = std::chrono::steady_clock;
using TimePoint = SteadyClock::time_point;
using Duration = SteadyClock::duration;

// Where "now" comes from. The real clock for running, the manual clock for tests and
// faster-than-real-time runs.
class Clock {
 public:
  virtual ~Clock() = default;
  [[nodiscard]] virtual TimePoint now() const = 0;
};

class RealClock final : public Clock {
 public:
  [[nodiscard]] TimePoint now() const override { return SteadyClock::now(); }
};

// A clock that moves only when told to. Starts at an arbitrary fixed epoch so that
// tests are deterministic.
class ManualClock final : public Clock {
 public:
  explicit ManualClock(TimePoint start = TimePoint{std::chrono::hours(1)}) : now_(start) {}
  [[nodiscard]] TimePoint now() const override { return now_; }
  void advance(Duration d) { now_ += d; }
  void set(TimePoint t) { now_ = t; }

 private:
  TimePoint now_;
};

}  // namespace rs4sim::stream
