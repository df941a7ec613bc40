#pragma once
// What every service of a run needs from the running process (rs4sim run / demo / a test),
// whatever its devices are: the stations' addresses, the clock (real or manual), the
// simulated bus for bus faults, and the event source. The RS4 services need more, the RS4s
// themselves: Rs4Target (rs4_target.h) adds them. A GridScan, METRON or Polaris run is a
// RunTarget only. Every call is made on the loop thread (through rpc::Executor).

#include "dp/link/memory_bus.h"
#include "dp/time/clock.h"
#include "stream/device_description.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace rs4sim::rpc {

class EventHub;
class Executor;
class Rs4Target;

// One station of the run (rs4sim.v1.Run/Describe's Station).
struct RunStation {
  std::uint8_t address;
  stream::DeviceKind kind;
};

class RunTarget {
 public:
  virtual ~RunTarget() = default;
  // The addresses of the run's stations (the RS4s of an RS4 run, the one device of a line run).
  [[nodiscard]] virtual std::vector<std::uint8_t> addresses() const = 0;
  [[nodiscard]] virtual dp::TimePoint now() const = 0;
  // True when the run is on the manual clock: time moves only through run_until.
  [[nodiscard]] virtual bool simulated() const = 0;
  // Simulated runs: advances time, checking `done` after every event, until it holds or
  // `limit` passed; returns done().
  virtual bool run_until(const std::function<bool()>& done, dp::Duration limit) = 0;
  // The simulated bus for bus faults; nullptr on a real link and on a byte line.
  virtual dp::link::MemoryBus* bus() = 0;
  // Runs `f` on the loop after `delay` (simulated runs: advances time by `delay` first).
  virtual void after(dp::Duration delay, std::function<void()> f) = 0;
  // What the run's devices are: the RS4, generic DP slaves (GSD stations), or the RS-485
  // device of a line run.
  [[nodiscard]] virtual stream::DeviceKind kind() const = 0;
  // Every station of the run with its kind; by default each of addresses() of kind(). A run
  // of several kinds (a bus file's) lists them all.
  [[nodiscard]] virtual std::vector<RunStation> stations() const {
    std::vector<RunStation> out;
    for (const auto a : addresses()) out.push_back({a, kind()});
    return out;
  }
  // A station of the run that is not an RS4, as the RS4 calls name it ("a GSD station
  // (rs4sim.v1.GsdStations)"); empty when the run has no other station at `address`.
  [[nodiscard]] virtual std::string other_station(std::uint8_t address) const {
    (void)address;
    return {};
  }
  // The source of Observation.StreamEvents (rpc/event_hub.h); nullptr = no event stream.
  virtual EventHub* events() { return nullptr; }
  // The run's RS4s for the RS4 calls; nullptr when it has none to serve (a byte line's run).
  virtual Rs4Target* rs4s() { return nullptr; }

 protected:
  RunTarget() = default;
  RunTarget(const RunTarget&) = default;
  RunTarget& operator=(const RunTarget&) = default;
};

// A call's run and the loop it runs on.
struct RunContext {
  RunTarget& target;
  Executor& executor;
};

}  // namespace rs4sim::rpc
