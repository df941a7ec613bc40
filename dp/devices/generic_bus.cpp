#include "dp/devices/generic_bus.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace rs4sim::dp::devices {

namespace {
master::MasterConfig master_config(const GenericBusConfig& c) {
  master::MasterConfig m;
  m.address = c.master_address;
  m.bus = master::BusParameters::defaults_for(c.baud);
  m.cycle_target = c.cycle_target;
  for (const auto& s : c.slaves) m.slaves.push_back(master_entry_for(s, c.watchdog));
  return m;
}
}  // namespace

GenericBus::GenericBus(const GenericBusConfig& config)
    : bus_(std::make_unique<link::MemoryBus>(clock_, config.bus)),
      master_(std::make_unique<master::Master>(master_config(config))) {
  bus_->attach(*master_);
  for (const auto& s : config.slaves) {
    slaves_.push_back(std::make_unique<GenericSlave>(s));
    bus_->attach(*slaves_.back());
  }
  bus_->start();
  collect();
}

GenericSlave& GenericBus::slave(std::uint8_t address) {
  return const_cast<GenericSlave&>(std::as_const(*this).slave(address));
}

const GenericSlave& GenericBus::slave(std::uint8_t address) const {
  for (const auto& s : slaves_) {
    if (s->address() == address) return *s;
  }
  throw std::out_of_range("generic bus: no slave at address " + std::to_string(address));
}

void GenericBus::run_for(Duration d) {
  run_until([] { return false; }, d);
}

std::vector<master::MasterEvent> GenericBus::take_events() {
  collect();
  return std::exchange(events_, {});
}

std::size_t GenericBus::slaves_in_data_exchange() const {
  std::size_t n = 0;
  for (const auto& s : slaves_) {
    if (master_->poll_state(s->address()) == master::PollState::kDataExchange) ++n;
  }
  return n;
}

}  // namespace rs4sim::dp::devices
