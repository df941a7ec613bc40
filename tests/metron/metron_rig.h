#pragma once
// A METRON device on a manual clock: send bytes, advance time deadline by deadline, and
// collect what the device transmits with the time it went out.

#include "metron/device.h"
#include "stream/clock.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <initializer_list>
#include <vector>

namespace rs4sim::metron::testing {

using Bytes = std::vector<std::uint8_t>;

struct Sent {
  stream::TimePoint at;
  Bytes bytes;
};

class Rig {
 public:
  explicit Rig(Options o) : device_(std::move(o)) { run_to(clock_.now()); }

  void send(std::initializer_list<std::uint8_t> bytes) { send(Bytes(bytes)); }
  void send(const Bytes& bytes) {
    device_.on_bytes(bytes, clock_.now());
    drain();
  }
  // Advances by `d`, calling on_time() at every deadline on the way.
  void advance(stream::Duration d) { run_to(clock_.now() + d); }
  void run_to(stream::TimePoint target) {
    while (true) {
      const auto d = device_.next_deadline();
      if (!d || *d > target) break;
      if (*d > clock_.now()) clock_.set(*d);
      device_.on_time(clock_.now());
      drain();
    }
    clock_.set(target);
  }
  // Sends `request` and returns everything transmitted within `window`.
  std::vector<Sent> exchange(const Bytes& request,
                             stream::Duration window = std::chrono::milliseconds(100)) {
    sent_.clear();
    send(request);
    advance(window);
    return sent_;
  }
  // The one frame answering `request` (a test failure if there is not exactly one).
  Bytes only_reply(const Bytes& request) {
    const auto s = exchange(request);
    EXPECT_EQ(s.size(), 1U) << "frames answering the request";
    return s.empty() ? Bytes{} : s.front().bytes;
  }
  std::vector<Sent> take() {
    auto s = std::move(sent_);
    sent_.clear();
    return s;
  }

  Device& device() { return device_; }
  stream::ManualClock& clock() { return clock_; }

 private:
  void drain() {
    while (auto f = device_.take_transmit()) sent_.push_back({clock_.now(), std::move(*f)});
  }

  stream::ManualClock clock_;
  Device device_;
  std::vector<Sent> sent_;
};

inline Options slave_options() { return Options{}; }
inline Options node_options(std::uint8_t node) {
  Options o;
  o.node_enabled = true;
  o.node = node;
  return o;
}

}  // namespace rs4sim::metron::testing
