#pragma once
// A GridScan device on the manual clock, for the device tests: power-up at t0, requests
// as raw bytes, answers drained with the time they left.

#include "gridscan/device.h"

#include <gtest/gtest.h>

#include <vector>

namespace rs4sim::gridscan::testing {

using Bytes = std::vector<std::uint8_t>;
using namespace std::chrono_literals;

struct Sent {
  Bytes bytes;
  stream::TimePoint at;
};

class DeviceHarness {
 public:
  explicit DeviceHarness(Options o = {}) : device(o) {}

  // Runs the device up to `now + d`, calling on_time at each deadline on the way.
  void run_for(stream::Duration d) {
    const auto end = clock.now() + d;
    for (;;) {
      drain();
      const auto next = device.next_deadline();
      if (!next || *next > end) break;
      clock.set(std::max(*next, clock.now()));
      device.on_time(clock.now());
    }
    clock.set(end);
    device.on_time(end);
    drain();
  }
  void start() { run_for(0ms); }
  // Power-up and the two power-up messages (A0 at t0, B0 at t0 + 1700 ms).
  void boot() {
    start();
    run_for(1700ms);
    sent.clear();
  }
  void send(const Bytes& b) {
    device.on_bytes(b, clock.now());
    drain();
  }
  // Sends a request and runs until the answer (or `limit`); returns what was sent.
  std::vector<Sent> exchange(const Bytes& b, stream::Duration limit = 100ms) {
    sent.clear();
    send(b);
    run_for(limit);
    return std::move(sent);
  }
  void drain() {
    while (auto f = device.take_transmit()) sent.push_back({std::move(*f), clock.now()});
  }

  stream::ManualClock clock;
  Device device;
  std::vector<Sent> sent;
};

// A valid request for `id` with SeqCnt `seq`.
inline Bytes request(std::uint8_t seq, CommandId id) {
  return encode(Frame{seq, request_id(id), {}});
}

}  // namespace rs4sim::gridscan::testing
