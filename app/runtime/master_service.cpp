#include "app/runtime/master_service.h"

#include "app/runtime/run_session.h"
#include "dp/link/memory_bus.h"
#include "rpc/bus_master_service.h"
#include "rpc/gsd_master_service.h"
#include "rs4/device/rs4_device.h"

#include <algorithm>
#include <ostream>

namespace rs4sim::app {

namespace device = rs4::device;

// The station the link runs: the master side, then the events of that call to the plugins
// and the report. Wake-ups of the master side (a plugin's record request) pass through.
class MasterService::Forwarder final : public dp::Station {
 public:
  explicit Forwarder(MasterService& service) : service_(service) {
    service_.station_.set_wake_handler([this] { wake(); });
  }
  ~Forwarder() override { service_.station_.set_wake_handler({}); }
  Forwarder(const Forwarder&) = delete;
  Forwarder& operator=(const Forwarder&) = delete;

  [[nodiscard]] std::uint8_t address() const override { return service_.station_.address(); }
  void on_telegram(const dp::fdl::Telegram& t, dp::TimePoint now) override {
    service_.station_.on_telegram(t, now);
    service_.dispatch(now);
  }
  void on_time(dp::TimePoint now) override {
    service_.station_.on_time(now);
    service_.dispatch(now);
  }
  [[nodiscard]] std::optional<dp::TimePoint> next_deadline() const override {
    return service_.station_.next_deadline();
  }
  std::optional<dp::fdl::Telegram> take_transmit() override {
    return service_.station_.take_transmit();
  }
  void on_malformed_frame(std::error_code why) override {
    service_.station_.on_malformed_frame(why);
  }

 private:
  MasterService& service_;
};

namespace {

rs4::device::Rs4MasterStationConfig with_gsd_slaves(const MasterServiceOptions& o,
                                                    const gsd::GsdMasterSlaves& gsd) {
  auto c = o.station;
  for (const auto& s : gsd.slaves()) {
    c.other_slaves.push_back(gsd_master_entry(s.spec, o.gsd_watchdog));
  }
  return c;
}

}  // namespace

MasterService::MasterService(const MasterServiceOptions& options, LinkKind link, std::ostream& out)
    : gsd_(options.gsd_slaves),
      station_(with_gsd_slaves(options, gsd_)),
      forwarder_(std::make_unique<Forwarder>(*this)),
      link_(link),
      json_(options.json),
      lost_hint_(options.lost_hint),
      out_(out) {}

MasterService::~MasterService() = default;

std::vector<dp::Station*> MasterService::stations() { return {forwarder_.get()}; }

void MasterService::start(dp::TimePoint now) {
  last_now_ = now;
  started_at_ = now;
  report_.emplace(out_, json_, now);
  report_->explain_lost_slaves(station_.master().config().bus.max_retry_limit, lost_hint_);
  for (auto* p : plugins_) p->start(station_, now);
}

void MasterService::announce() const {
  if (announced_ || !report_) return;
  announced_ = true;
  report_->started(station_, link_name(link_));
  gsd_report_.start(*report_, started_at_);
}

std::string MasterService::describe() const {
  std::string list;
  for (const auto a : station_.slave_addresses()) {
    list += (list.empty() ? "" : ", ") + std::to_string(a);
  }
  std::string text = "class 1 master " + std::to_string(station_.address());
  if (!list.empty()) text += " with PROFIsafe F-host for RS4 " + list + " (from the GSD)";
  if (!gsd_.empty()) {
    text += list.empty() ? " for" : ", and";
    text += " GSD slave " + gsd_.address_list() + " (from their GSDs";
    if (gsd_.f_module_count() > 0) text += ", PROFIsafe F-host for their F-modules";
    text += ")";
  }
  return text;
}

void MasterService::print_status(std::ostream& out, const dp::link::StationCounters& link) const {
  (void)out, (void)link;  // the report writes to the service's stream
  if (!report_) return;
  announce();  // a run stopped before its loop ran
  report_->stopped(station_, last_now_);
  gsd_report_.stopped(station_.master(), *report_, last_now_);
}

bool MasterService::healthy() const {
  for (const auto a : station_.slave_addresses()) {
    const auto v = station_.view(a);
    if (!v || !v->data_exchange() || v->safety != profisafe::FHostState::kRun) return false;
  }
  return gsd_.healthy(station_.master());
}

void MasterService::dispatch(dp::TimePoint now) {
  announce();
  last_now_ = now;
  events_.clear();
  station_.take_events(events_);
  if (events_.empty() || !report_) return;
  // The GSD F-modules' F-hosts on the master's cycle, as the RS4s' run inside the station.
  const auto cycle = [](const auto& e) {
    return std::holds_alternative<rs4::device::MasterCycle>(e);
  };
  if (gsd_.f_module_count() > 0 && std::any_of(events_.begin(), events_.end(), cycle)) {
    gsd_.on_master_cycle(station_.master(), now, station_.auto_ack_rei());
  }
  for (auto* p : plugins_) {
    for (const auto& e : events_) p->on_event(e, station_, *report_, now);
  }
  report_->events(events_, station_, now);
  gsd_report_.update(station_.master(), *report_, now);
}

namespace {

constexpr double kDefaultSimulatedSeconds = 40;  // past the RS4's ≈30 s boot [RS4 manual §7.1.1]

// The RS4s simulated beside the master on the in-memory bus, on the manual clock.
int run_memory(const MasterServiceOptions& o, const LinkOptions& l, std::ostream& out,
               const std::vector<MasterPlugin*>& plugins) {
  RunSession session(out);
  dp::ManualClock clock;
  MasterService service(o, LinkKind::kMemory, out);
  for (auto* p : plugins) service.add_plugin(*p);
  std::vector<std::unique_ptr<device::Rs4Device>> devices;
  for (const auto& s : o.station.slaves) {
    device::Rs4DeviceConfig c;
    c.switches = device::switches_for(s.address);
    c.boot_time = std::chrono::milliseconds(o.simulated_boot_ms);
    devices.push_back(std::make_unique<device::Rs4Device>(c));
  }
  std::vector<std::unique_ptr<GsdStation>> gsd_stations;
  for (const auto& spec : o.gsd_slaves) gsd_stations.push_back(std::make_unique<GsdStation>(spec));
  dp::link::MemoryBus bus(clock);
  const auto capture = open_link_capture(l, clock.now());
  attach_capture(capture.get(), bus);
  for (auto* s : service.stations()) bus.attach(*s);
  for (auto& d : devices) bus.attach(*d);
  for (auto& g : gsd_stations) bus.attach(*g);
  service.start(clock.now());
  bus.start();
  for (auto& d : devices) d->power_on(clock.now());
  run_simulated(session, l.duration > 0 ? l.duration : kDefaultSimulatedSeconds,
                [&](dp::Duration d) { bus.run_for(d); });
  service.print_status(out, {});
  const bool written = report_capture(capture.get(), l);
  return service.healthy() && written ? 0 : 1;
}

}  // namespace

ServiceList MasterService::services(const ServiceContext& context) {
  // The master's own view of its stations (the page's station list and counters), its GSD
  // slaves' I/O, then the plugins' services.
  ServiceList all{
      std::make_shared<rpc::BusMasterService>(station_, context.clock, context.executor)};
  if (!gsd_.empty()) {
    all.push_back(std::make_shared<rpc::GsdMasterService>(
        context.executor, gsd_, [this]() -> dp::master::Master& { return station_.master(); }));
  }
  for (auto* p : plugins_) {
    auto some = p->services(context);
    all.insert(all.end(), some.begin(), some.end());
  }
  return all;
}

void MasterService::stop_services() {
  for (auto* p : plugins_) p->stop_services();
}

std::string lost_slave_hint(const LinkOptions& link) {
  // Seen on a busy 2-core machine: a slave process on a pty read nothing for 79 ms, then seven
  // telegrams at once; with --rt-priority 50 on it, no losses (docs/serial.md).
  const bool pty = link.link == LinkKind::kPty || link.port.rfind("/dev/pts/", 0) == 0;
  if (pty) {
    return "on a loaded machine a slave process on a pty may be starved of CPU time: run it "
           "with --rt-priority 50 (docs/serial.md)";
  }
  if (link.link == LinkKind::kUdp) {
    return "a slave process on a loaded machine may be starved of CPU time: run it with "
           "--rt-priority 50 (docs/serial.md)";
  }
  if (link.link == LinkKind::kSerial) {
    return "check the line (wiring, termination, rate) and that the slave answers within the "
           "slot time (docs/serial.md)";
  }
  return {};
}

int run_master(const MasterServiceOptions& options, const LinkOptions& link, std::ostream& out,
               const std::vector<MasterPlugin*>& plugins) {
  validate(link);
  if (link.link == LinkKind::kMemory) return run_memory(options, link, out, plugins);
  MasterServiceOptions with_hint = options;
  with_hint.lost_hint = lost_slave_hint(link);
  MasterService service(with_hint, link.link, out);  // outlives the session's server
  RunSession session(out);
  for (auto* p : plugins) service.add_plugin(*p);
  return run_on_link(session, service, link, out);
}

}  // namespace rs4sim::app
