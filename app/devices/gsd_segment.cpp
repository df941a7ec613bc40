#include "app/devices/gsd_segment.h"

#include "app/devices/gsd_service.h"
#include "app/runtime/usage_error.h"
#include "dp/time/baud_rate.h"
#include "rpc/event_hub.h"
#include "rpc/rs4_services.h"
#include "rpc/rs4_target.h"

#include <algorithm>
#include <array>
#include <ostream>

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
  for (auto& s : specs) {
    stations_.push_back(std::make_unique<GsdStation>(std::move(s)));
    bus_->attach(*stations_.back());
  }
  bus_->start();
}

// The run as the shared services see it: the GSD stations' addresses, no RS4 (the RS4 calls
// answer FAILED_PRECONDITION), the manual clock moved by SimTime, the bus for bus faults, and an
// event hub that watches every station and is polled after each bus event.
class GsdSegment::Target final : public rpc::Rs4Target {
 public:
  explicit Target(GsdSegment& segment) : segment_(segment) {
    for (auto& s : segment.stations_) hub_->watch(gsd_watcher(*s));
    // The observer holds the hub, not this target: the bus may call it after the target is
    // gone (the segment ends after the server).
    std::array<bool, 128> station{};  // the addresses whose telegrams the stream carries
    for (const auto& s : segment.stations_) station[s->address()] = true;
    segment.bus_->add_observer(
        [hub = hub_, station, &clock = segment.clock_](const dp::link::BusEvent& e) {
          if (hub->wants_telegrams()) {
            const auto fate = dp::link::to_string(e.fate);
            if (station[e.from & 127U]) {
              hub->telegram(e.from, v1::DIRECTION_FROM_STATION, e.wire, fate, e.time);
            }
            if (e.to && station[*e.to & 127U]) {
              hub->telegram(*e.to, v1::DIRECTION_TO_STATION, e.wire, fate, e.time);
            }
          }
          hub->poll(clock.now());
        });
  }
  [[nodiscard]] std::vector<std::uint8_t> addresses() const override {
    std::vector<std::uint8_t> out;
    for (const auto& s : segment_.stations_) out.push_back(s->address());
    return out;
  }
  rs4::device::Rs4Device* device(std::uint8_t) override { return nullptr; }
  [[nodiscard]] dp::TimePoint now() const override { return segment_.clock_.now(); }
  [[nodiscard]] bool simulated() const override { return true; }
  bool run_until(const std::function<bool()>& done, dp::Duration limit) override {
    const bool reached = segment_.bus_->run_until(done, segment_.clock_.now() + limit, [this] {
      segment_.master_->take_events(segment_.events_);
      segment_.events_.clear();
    });
    hub_->poll(now());
    return reached;
  }
  void after(dp::Duration delay, std::function<void()> f) override {
    segment_.run_for(delay);
    f();
    hub_->poll(now());
  }
  dp::link::MemoryBus* bus() override { return segment_.bus_.get(); }
  rpc::EventHub* events() override { return hub_.get(); }
  [[nodiscard]] std::string kind() const override { return "gsd"; }

 private:
  GsdSegment& segment_;
  std::shared_ptr<rpc::EventHub> hub_ = std::make_shared<rpc::EventHub>();
};

GsdSegment::~GsdSegment() = default;

ServiceList GsdSegment::services(const ServiceContext& context) {
  target_ = std::make_unique<Target>(*this);
  std::vector<GsdStation*> stations;
  for (auto& s : stations_) stations.push_back(s.get());
  auto* hub = target_->events();
  GsdServiceContext g{context.executor, std::move(stations),
                      [hub, this] { hub->poll(clock_.now()); }, bus_.get()};
  const rpc::Rs4Context rs4{*target_, context.executor};
  return {std::make_shared<GsdStationsService>(std::move(g)),
          std::make_shared<rpc::SimTimeService>(rs4),
          std::make_shared<rpc::ObservationService>(rs4)};
}

void GsdSegment::run_for(dp::Duration d) {
  bus_->run_until([] { return false; }, clock_.now() + d, [this] { master_->take_events(events_); });
  events_.clear();
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
