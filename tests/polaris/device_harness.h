#pragma once
// Drives a polaris::Device on a ManualClock: sends request bytes, runs the clock from
// deadline to deadline, and collects what the device transmits with the time it did.

#include "polaris/device.h"
#include "stream/clock.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace rs4sim::polaris::test {

using Bytes = std::vector<std::uint8_t>;

struct Sent {
  Bytes bytes;
  stream::TimePoint at;
};

class Harness {
 public:
  explicit Harness(const Options& o) : device(o) { device.on_time(clock.now()); }

  // Sends `request` at now and runs the clock until the device is idle or `limit` passed;
  // returns the first frame transmitted.
  std::optional<Sent> exchange(const Bytes& request,
                               stream::Duration limit = std::chrono::milliseconds(50)) {
    device.on_bytes(request, clock.now());
    return run_until_sent(clock.now() + limit);
  }

  std::optional<Sent> run_until_sent(stream::TimePoint until) {
    for (;;) {
      if (auto frame = device.take_transmit()) return Sent{*frame, clock.now()};
      const auto next = device.next_deadline();
      if (!next || *next > until) {
        clock.set(until);
        device.on_time(until);
        if (auto frame = device.take_transmit()) return Sent{*frame, clock.now()};
        return std::nullopt;
      }
      clock.set(std::max(*next, clock.now()));
      device.on_time(clock.now());
    }
  }

  stream::ManualClock clock;
  Device device;
};

}  // namespace rs4sim::polaris::test
