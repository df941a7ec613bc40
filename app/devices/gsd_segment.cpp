#include "app/devices/gsd_segment.h"

#include "app/devices/memory_bus_target.h"
#include "app/runtime/usage_error.h"
#include "dp/time/baud_rate.h"
#include "rpc/diagnosis_service.h"
#include "rpc/event_hub.h"
#include "rpc/gsd_service.h"
#include "rpc/rs4_services.h"

#include <algorithm>
#include <ostream>
#include <variant>

namespace rs4sim::app {

std::uint8_t free_master_address(const std::vector<std::uint8_t>& stations) {
  for (std::uint8_t a = 1; a < 126; ++a) {
    if (std::find(stations.begin(), stations.end(), a) == stations.end()) return a;
  }
  return 0;
}

void fit_max_tsdr(dp::master::BusParameters& bus, std::uint16_t max_tsdr) {
  if (max_tsdr <= bus.max_tsdr) return;
  if (max_tsdr > 1023 || bus.tsl + (max_tsdr - bus.max_tsdr) > 16383) {
    throw UsageError("MaxTsdr " + std::to_string(max_tsdr) +
                     " Tbit is beyond what the bus parameters allow (max TSDR 1023, TSL 16383, "
                     "[IEC 61158-4-3 bus parameters, timing])");
  }
  bus.tsl += max_tsdr - bus.max_tsdr;
  bus.max_tsdr = max_tsdr;
  bus.tid2 = std::max(bus.tid2, bus.max_tsdr);
}

GsdSegment::GsdSegment(std::vector<GsdStationSpec> specs, const std::string& baud,
                       dp::Duration cycle_target) {
  const auto rate = dp::parse_baud_rate(baud);
  if (!rate) throw UsageError("--baud " + baud + " is not a PROFIBUS rate");
  dp::master::MasterConfig m;
  m.bus = dp::master::BusParameters::defaults_for(*rate);
  m.cycle_target = cycle_target;
  std::vector<std::uint8_t> addresses;
  for (const auto& s : specs) {
    check_gsd_baud(s, baud);
    if (const auto t = gsd_max_tsdr(s, baud)) fit_max_tsdr(m.bus, *t);
    m.slaves.push_back(gsd_master_entry(s, std::chrono::milliseconds(100)));
    addresses.push_back(s.address);
  }
  master_address_ = free_master_address(addresses);
  m.address = master_address_;
  bus_ = std::make_unique<dp::link::MemoryBus>(clock_);
  master_ = std::make_unique<dp::master::Master>(m);
  bus_->attach(*master_);
  std::vector<GsdStationSpec> hosted = specs;
  for (auto& s : hosted) s.f_dest_add.reset();
  f_hosts_ = std::make_unique<gsd::GsdMasterSlaves>(std::move(hosted));
  for (auto& s : specs) {
    stations_.push_back(std::make_unique<GsdStation>(std::move(s)));
    bus_->attach(*stations_.back());
  }
  bus_->start();
}

void GsdSegment::drain() {
  master_->take_events(events_);
  for (const auto& e : events_) {
    if (std::holds_alternative<dp::master::CycleCompleted>(e)) {
      (void)f_hosts_->on_master_cycle(*master_, clock_.now(), false);
    }
  }
  events_.clear();
}

GsdSegment::~GsdSegment() = default;

// The shared services (Diagnostics among them) see the GSD stations and no RS4 (the RS4 calls answer
// FAILED_PRECONDITION), on this segment's clock.
ServiceList GsdSegment::services(const ServiceContext& context) {
  std::vector<GsdStation*> stations;
  for (auto& s : stations_) stations.push_back(s.get());
  target_ = std::make_unique<MemoryBusTarget>(
      clock_, *bus_,
      [this] { drain(); },
      [&stations] {
        ServedStations s;
        s.gsd = stations;
        return s;
      }());
  auto* hub = target_->events();
  for (const auto& s : stations_) {
    if (!s->application().f_modules().empty()) hub->watch(rpc::gsd_fhost_watcher(*s, *f_hosts_));
  }
  const rpc::Rs4Context rs4{*target_, context.executor};
  auto diagnostics = std::make_shared<rpc::DiagnosticsService>(rs4, stations);
  rpc::GsdServiceContext g{context.executor, std::move(stations),
                           [hub, this] { hub->poll(clock_.now()); }, bus_.get()};
  g.f_hosts = f_hosts_.get();
  return {std::make_shared<rpc::GsdStationsService>(std::move(g)),
          std::make_shared<rpc::SimTimeService>(rs4),
          std::make_shared<rpc::ObservationService>(rs4), std::move(diagnostics)};
}

void GsdSegment::run_for(dp::Duration d) {
  bus_->run_until([] { return false; }, clock_.now() + d, [this] { drain(); });
}

std::size_t GsdSegment::in_data_exchange() const {
  std::size_t n = 0;
  for (const auto& s : stations_) {
    if (master_->poll_state(s->address()) == dp::master::PollState::kDataExchange) ++n;
  }
  return n;
}

bool GsdSegment::healthy() const { return in_data_exchange() == stations_.size(); }

void GsdSegment::print_summary(std::ostream& out) const {
  out << ": " << master_->counters().cycles << " cycles, " << in_data_exchange() << " of "
      << stations_.size() << " GSD stations in data exchange" << std::endl;
  for (const auto& s : stations_) {
    const auto& c = bus_->counters(s->address());
    out << s->describe() << ": state " << dp::slave::to_string(s->slave().state())
        << ", data exchanges " << s->application().exchanges() << ", telegrams received "
        << c.received << ", sent " << c.sent;
    if (!s->application().prm_fault().empty()) {
      out << ", Set_Prm refused: " << s->application().prm_fault();
    }
    out << std::endl;
  }
}

}  // namespace rs4sim::app
