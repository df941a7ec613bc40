// Device entry `generic`: a generic DP-V1 slave (dp/devices) with the Ident_Number and
// configuration identifiers given on the command line.
#include "app/demos/demos.h"
#include "app/devices/device_options.h"
#include "app/devices/device_registry.h"
#include "app/runtime/run_options.h"
#include "dp/devices/generic_bus.h"

#include <cstdio>
#include <iostream>

namespace rs4sim::app {
namespace {

using dp::devices::GenericSlave;
using dp::devices::GenericSlaveConfig;

void trace(GenericSlave& s) {
  s.slave().set_trace([a = s.address()](const dp::slave::Transition& t) {
    std::cout << "slave " << int(a) << ": " << dp::slave::to_string(t.from) << " -> "
              << dp::slave::to_string(t.to) << " (" << dp::slave::to_string(t.why) << ")"
              << std::endl;
  });
}

void print_slave(std::ostream& out, const GenericSlave& s, const dp::link::StationCounters& c) {
  out << "slave " << int(s.address()) << ": state " << dp::slave::to_string(s.slave().state())
      << ", data exchanges " << s.device().exchanges() << ", telegrams received " << c.received
      << ", sent " << c.sent << ", malformed " << c.malformed << ", link errors " << c.send_errors
      << std::endl;
}

GenericSlaveConfig slave_config(const DeviceOptions& o) {
  return generic_slave_config(o.address.value_or(-1), o.ident, o.cfg);
}

class GenericInstance final : public DeviceInstance {
 public:
  explicit GenericInstance(const GenericSlaveConfig& c) : config_(c), slave_(c) { trace(slave_); }
  std::vector<dp::Station*> stations() override { return {&slave_}; }
  [[nodiscard]] std::string describe() const override {
    char ident[8];
    std::snprintf(ident, sizeof ident, "%x", config_.ident_number);
    return "generic slave " + std::to_string(config_.address) + " (ident 0x" + ident + ", cfg " +
           hex(config_.cfg) + ")";
  }
  void print_status(std::ostream& out, const dp::link::StationCounters& link) const override {
    print_slave(out, slave_, link);
  }

 private:
  GenericSlaveConfig config_;
  GenericSlave slave_;
};

class GenericSegment final : public SimulatedSegment {
 public:
  explicit GenericSegment(const GenericSlaveConfig& c) : address_(c.address), bus_(bus_config(c)) {
    trace(bus_.slave(address_));
  }
  void run_for(dp::Duration d) override { bus_.run_for(d); }
  [[nodiscard]] std::uint8_t master_address() const override { return address_ == 1 ? 2 : 1; }
  void print_summary(std::ostream& out) const override {
    out << ": " << bus_.master().counters().cycles << " cycles" << std::endl;
    print_slave(out, bus_.slave(address_), bus_.bus().counters(address_));
  }
  [[nodiscard]] bool healthy() const override { return bus_.slaves_in_data_exchange() == 1; }
  dp::link::MemoryBus* bus() override { return &bus_.bus(); }

 private:
  static dp::devices::GenericBusConfig bus_config(const GenericSlaveConfig& c) {
    dp::devices::GenericBusConfig bc;
    bc.slaves = {c};
    bc.master_address = c.address == 1 ? 2 : 1;
    return bc;
  }
  std::uint8_t address_;
  dp::devices::GenericBus bus_;
};

void validate(DeviceOptions& o) {
  if (!o.address || o.ident.empty() || o.cfg.empty()) {
    throw UsageError("--device generic needs --address, --ident and --cfg");
  }
  refuse_unused(o, "generic", {DeviceFlag::kAddress, DeviceFlag::kIdent, DeviceFlag::kCfg});
  (void)slave_config(o);  // throws UsageError for a bad address, ident or cfg
}

}  // namespace

DeviceEntry generic_device_entry() {
  return {
      "generic",
      10.0,
      validate,
      [](const DeviceOptions& o) { return std::make_unique<GenericInstance>(slave_config(o)); },
      [](const DeviceOptions& o) { return std::make_unique<GenericSegment>(slave_config(o)); },
      run_generic_demo,
  };
}

}  // namespace rs4sim::app
