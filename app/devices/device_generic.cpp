// Device entry `generic`: a generic DP-V1 slave (dp/devices) with the Ident_Number and
// configuration identifiers given on the command line, or any DP slave from its GSD
// (--gsd FILE [--module NAME]..., app/devices/gsd_station_file.h).
#include "app/demos/demos.h"
#include "app/devices/device_options.h"
#include "app/devices/device_registry.h"
#include "app/devices/gsd_segment.h"
#include "app/devices/gsd_station_file.h"
#include "app/runtime/run_options.h"
#include "dp/devices/description.h"
#include "dp/devices/generic_bus.h"
#include "rpc/device_target.h"
#include "rpc/diagnosis_service.h"
#include "rpc/gsd_service.h"
#include "rpc/rs4_services.h"
#include "rpc/tapped_station.h"

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
  ServedStations served_stations() override {
    ServedStations s;
    s.others.push_back({config_.address, "a generic slave (--ident/--cfg: no API of its own)"});
    return s;
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

// --gsd: the station the GSD describes, with rs4sim.v1.GsdStations and the event stream
// (docs/gsd.md "Harness API").
class GsdInstance final : public DeviceInstance {
 public:
  explicit GsdInstance(GsdStationSpec spec) : station_(std::move(spec)) {}
  std::vector<dp::Station*> stations() override { return {&tap_}; }
  ServiceList services(const ServiceContext& c) override {
    target_ = std::make_unique<rpc::LineDeviceTarget>(stream::DeviceKind::kGeneric,
                                                      rpc::gsd_watcher(station_), c.clock, c.io);
    tap_.set_hub(target_->events());
    auto* hub = target_->events();
    const dp::Clock& clock = c.clock;
    rpc::GsdServiceContext g{c.executor, {&station_}, [hub, &clock] { hub->poll(clock.now()); }};
    g.turnaround = c.turnaround;
    g.slot_time_us = c.slot_time_us;
    const rpc::RunContext run{*target_, c.executor};
    return {std::make_shared<rpc::GsdStationsService>(std::move(g)),
            std::make_shared<rpc::ObservationService>(run),
            std::make_shared<rpc::DiagnosticsService>(run, std::vector<GsdStation*>{&station_})};
  }
  void stop_services() override {
    if (target_) target_->stop();
  }
  ServedStations served_stations() override {
    ServedStations s;
    s.gsd.push_back(&station_);
    s.taps.push_back(&tap_);
    return s;
  }
  [[nodiscard]] std::string describe() const override { return station_.describe(); }
  void print_status(std::ostream& out, const dp::link::StationCounters& c) const override {
    out << "slave " << int(station_.address()) << ": state "
        << dp::slave::to_string(station_.slave().state()) << ", data exchanges "
        << station_.application().exchanges() << ", telegrams received " << c.received << ", sent "
        << c.sent << ", malformed " << c.malformed << ", link errors " << c.send_errors;
    if (!station_.application().prm_fault().empty()) {
      out << ", Set_Prm refused: " << station_.application().prm_fault();
    }
    out << std::endl;
  }

 private:
  GsdStation station_;
  rpc::TappedStation tap_{station_};  // telegrams for the event stream
  std::unique_ptr<rpc::LineDeviceTarget> target_;
};

GsdStationSpec gsd_spec(const DeviceOptions& o, std::vector<std::string>* warnings) {
  GsdStationSpec spec = load_gsd_station(o.gsd, o.modules, o.address.value_or(-1), warnings);
  check_gsd_baud(spec, o.link_baud);
  if (o.f_dest_add) spec.f_dest_add = check_f_dest_add(spec, *o.f_dest_add);
  return spec;
}

void validate_gsd(DeviceOptions& o) {
  if (!o.address) throw UsageError("--device generic --gsd needs --address");
  refuse_unused(o, "generic --gsd", {DeviceFlag::kAddress, DeviceFlag::kGsd, DeviceFlag::kModule,
                                          DeviceFlag::kFDestAdd});
  std::vector<std::string> warnings;
  GsdStationSpec spec = gsd_spec(o, &warnings);
  for (const auto& w : warnings) std::cerr << "warning: " << w << std::endl;
  try {
    GsdStation probe(std::move(spec));
  } catch (const std::system_error& e) {
    throw UsageError(o.gsd + ": the slave cannot take this GSD: " + e.what());
  }
}

void validate(DeviceOptions& o) {
  if (!o.gsd.empty()) return validate_gsd(o);
  if (!o.modules.empty()) throw UsageError("--module needs --gsd FILE");
  if (!o.address || o.ident.empty() || o.cfg.empty()) {
    throw UsageError("--device generic needs --address, --ident and --cfg (or --gsd FILE)");
  }
  refuse_unused(o, "generic", dp::devices::description().options);
  (void)slave_config(o);  // throws UsageError for a bad address, ident or cfg
}

}  // namespace

DeviceEntry generic_device_entry() {
  return {
      "generic",
      10.0,
      validate,
      [](const DeviceOptions& o) -> std::unique_ptr<DeviceInstance> {
        if (!o.gsd.empty()) return std::make_unique<GsdInstance>(gsd_spec(o, nullptr));
        return std::make_unique<GenericInstance>(slave_config(o));
      },
      [](const DeviceOptions& o) -> std::unique_ptr<SimulatedSegment> {
        if (!o.gsd.empty()) {
          std::vector<GsdStationSpec> specs;
          specs.push_back(gsd_spec(o, nullptr));
          return std::make_unique<GsdSegment>(std::move(specs), o.link_baud);
        }
        return std::make_unique<GenericSegment>(slave_config(o));
      },
      run_generic_demo,
      false,
      dp::devices::description().options,
      dp::devices::description().kind,
  };
}

}  // namespace rs4sim::app
