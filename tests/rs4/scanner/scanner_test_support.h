#pragma once
// Shared fixture for the scanner tests: a manual "now" that only moves when told.
#include "rs4/scanner/scanner.h"

#include <gtest/gtest.h>

#include <chrono>

namespace rs4sim::rs4::scanner::testing {

using std::chrono::milliseconds;
using std::chrono::seconds;

inline constexpr TimePoint kT0{std::chrono::hours(1)};

struct ManualTime {
  TimePoint now = kT0;
  TimePoint advance(std::chrono::nanoseconds d) {
    now += std::chrono::duration_cast<TimePoint::duration>(d);
    return now;
  }
};

// A parameter set with the given restart mode and n (response time 80 + n·40 ms).
inline ParameterSet params(RestartMode mode, std::uint8_t steps = 0) {
  ParameterSet p = factory_default();
  p.restart_mode = mode;
  p.response_steps = steps;
  return p;
}

// A scanner with `set`, powered on at kT0 and booted (measuring from kT0 + 30 s).
inline Scanner booted(const ParameterSet& set, ManualTime& t) {
  Scanner s;
  EXPECT_TRUE(s.set_parameters(set, t.now));
  s.power_on(t.now);
  s.advance(t.advance(seconds(30)));
  return s;
}

// A 200 ms pulse on the restart input from now (within the 0.12 … 5 s the manual allows,
// [RS4 manual §4.3]).
inline void pulse(Scanner& s, ManualTime& t) {
  s.set_restart_input(true, t.now);
  s.set_restart_input(false, t.advance(milliseconds(200)));
}

// A booted scanner with restart `mode` (an interlock), started by a pulse.
inline Scanner started(RestartMode mode, ManualTime& t) {
  Scanner s = booted(params(mode), t);
  pulse(s, t);
  return s;
}

// Circle that violates the factory protective field of pair 1 (1000 mm) straight ahead.
inline Shape intruder(double distance_mm = 600) { return Circle{{0, distance_mm}, 50}; }

}  // namespace rs4sim::rs4::scanner::testing
