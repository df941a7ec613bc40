#pragma once
// A powered RS4 (adapter + scanner, no bus) with its RS232 port on a manual clock, for the
// port's tests: feed bytes, run the clock through the port's deadlines, collect frames.
#include "rs4/adapter/adapter.h"
#include "rs4/rs232/rs232_client.h"
#include "rs4/rs232/rs232_port.h"
#include "stream/clock.h"

#include <chrono>
#include <cstdint>
#include <memory>
#include <vector>

namespace rs4sim::rs4::rs232::testing {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;

inline adapter::AdapterConfig quick_boot() {
  adapter::AdapterConfig c;
  c.scanner.boot_duration = 100ms;
  return c;
}

struct PortFixture {
  explicit PortFixture(const PortOptions& options = {},
                       const adapter::AdapterConfig& config = quick_boot())
      : adapter(config), port(adapter, options) {}

  // Powers the RS4 on and runs until it measures.
  void boot() {
    adapter.power_on(clock.now());
    run_for(200ms);
  }
  std::vector<Bytes> feed(const Bytes& bytes) {
    port.on_bytes(bytes, clock.now());
    return drain();
  }
  std::vector<Bytes> drain() {
    std::vector<Bytes> frames;
    while (auto f = port.take_transmit()) frames.push_back(std::move(*f));
    return frames;
  }
  // Advances through every port deadline up to now + d; the frames sent on the way.
  std::vector<Bytes> run_for(stream::Duration d) {
    const auto end = clock.now() + d;
    std::vector<Bytes> frames;
    for (int guard = 0; guard < 1'000'000; ++guard) {
      auto next = port.next_deadline();
      if (const auto a = adapter.next_deadline(); a && (!next || *a < *next)) next = a;
      if (!next || *next > end) break;
      if (*next > clock.now()) clock.set(*next);
      adapter.on_time(clock.now());
      port.on_time(clock.now());
      for (auto& f : drain()) frames.push_back(std::move(f));
    }
    clock.set(end);
    port.on_time(end);
    for (auto& f : drain()) frames.push_back(std::move(f));
    return frames;
  }
  // One answer decoded from one frame (client side).
  static Answer decode(const Bytes& frame) {
    AnswerReader reader;
    auto answers = reader.feed(frame);
    if (answers.size() != 1 || !answers[0]) return Acknowledge{};
    return answers[0].value();
  }

  stream::ManualClock clock;
  adapter::Adapter adapter;
  Rs232Port port;
};

}  // namespace rs4sim::rs4::rs232::testing
