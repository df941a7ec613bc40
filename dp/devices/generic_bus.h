#pragma once
// A whole simulated segment in one object: our class 1 master and generic slaves on a
// link::MemoryBus with a ManualClock. Used by `rs4sim demo`, `rs4sim run --link memory`,
// the integration tests and the benchmarks.

#include "dp/devices/generic_master_config.h"
#include "dp/link/memory_bus.h"
#include "dp/master/master.h"

#include <functional>
#include <memory>
#include <vector>

namespace rs4sim::dp::devices {

struct GenericBusConfig {
  std::uint8_t master_address = 1;
  std::vector<GenericSlaveConfig> slaves;
  link::MemoryBusConfig bus;  // wire model off by default: replies arrive at once
  BaudRate baud = BaudRate::k12M;
  Duration cycle_target = std::chrono::milliseconds(10);
  std::chrono::milliseconds watchdog{100};
};

class GenericBus {
 public:
  // Throws std::system_error / std::invalid_argument for a bad configuration.
  explicit GenericBus(const GenericBusConfig& config);

  [[nodiscard]] ManualClock& clock() { return clock_; }
  [[nodiscard]] link::MemoryBus& bus() { return *bus_; }
  [[nodiscard]] const link::MemoryBus& bus() const { return *bus_; }
  [[nodiscard]] master::Master& master() { return *master_; }
  [[nodiscard]] const master::Master& master() const { return *master_; }
  // Throws std::out_of_range for an address without a slave.
  [[nodiscard]] GenericSlave& slave(std::uint8_t address);
  [[nodiscard]] const GenericSlave& slave(std::uint8_t address) const;
  [[nodiscard]] std::size_t slave_count() const { return slaves_.size(); }

  // Simulated time runs until `done()` holds (checked after every bus event) or `timeout`
  // of simulated time has passed; returns done(). Master events are collected.
  template <class Done>
  bool run_until(Done&& done, Duration timeout) {
    return bus_->run_until_with(done, clock_.now() + timeout, [this] { collect(); });
  }
  void run_for(Duration d);

  // Master events collected so far; take_events() moves them out.
  [[nodiscard]] const std::vector<master::MasterEvent>& events() const { return events_; }
  std::vector<master::MasterEvent> take_events();

  // Slaves currently in data exchange according to the master.
  [[nodiscard]] std::size_t slaves_in_data_exchange() const;

 private:
  void collect() { master_->take_events(events_); }  // appends

  ManualClock clock_;
  std::unique_ptr<link::MemoryBus> bus_;
  std::unique_ptr<master::Master> master_;
  std::vector<std::unique_ptr<GenericSlave>> slaves_;
  std::vector<master::MasterEvent> events_;
};

}  // namespace rs4sim::dp::devices
