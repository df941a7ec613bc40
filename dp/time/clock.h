#pragma once
// dp's names for the injected clock, which lives in the byte-stream layer below
// (stream/clock.h, [docs/design.md#injected-time]).

#include "stream/clock.h"

namespace rs4sim::dp {

using ::rs4sim::stream::Clock;
using ::rs4sim::stream::Duration;
using ::rs4sim::stream::ManualClock;
using ::rs4sim::stream::RealClock;
using ::rs4sim::stream::SteadyClock;
using ::rs4sim::stream::TimePoint;

}  // namespace rs4sim::dp
