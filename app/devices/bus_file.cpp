// The bus file (bus_file.h). JSON is read with protobuf's JSON parser into a
// google.protobuf.Value, as the parameter documents and archive files are: Debian 12's Boost
// (1.74) has no Boost.JSON (it came with 1.75), and the project links protobuf anyway
// (docs/decisions.md).
#include "app/devices/bus_file.h"

#include "app/devices/device_options.h"
#include "app/devices/gsd_segment.h"
#include "app/devices/gsd_station_file.h"
#include "app/devices/memory_bus_target.h"
#include "app/runtime/run_options.h"
#include "app/runtime/usage_error.h"
#include "app/runtime/whole_file.h"
#include "dp/devices/generic_master_config.h"
#include "dp/link/memory_bus.h"
#include "dp/master/master.h"
#include "dp/pdu/sap.h"
#include "json/message.h"
#include "json/path.h"
#include "json/syntax.h"
#include "json/value_kind.h"
#include "rpc/device_target.h"
#include "rpc/gsd_service.h"
#include "rpc/rs4_services.h"
#include "rpc/tapped_station.h"
#include "rs4/device/rs4_device.h"
#include "rs4/device/rs4_master.h"

#include <google/protobuf/struct.pb.h>
#include <google/protobuf/util/json_util.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <ostream>
#include <sstream>
#include <string_view>

namespace rs4sim::app {
namespace {

using google::protobuf::Value;

using json::kind_of;

class Reader {
 public:
  Reader(std::string file, std::string dir) : file_(std::move(file)), dir_(std::move(dir)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& reason) const {
    throw UsageError(file_ + ": " + path + ": " + reason);
  }
  const std::string& text(const Value& v, const std::string& path) const {
    if (v.kind_case() != Value::kStringValue) fail(path, "expected a string, got " + kind_of(v));
    return v.string_value();
  }
  long long integer(const Value& v, const std::string& path, long long lo, long long hi) const {
    if (v.kind_case() != Value::kNumberValue) fail(path, "expected an integer, got " + kind_of(v));
    const double d = v.number_value();
    if (d != std::floor(d)) fail(path, "expected an integer, got " + number(d));
    if (d < static_cast<double>(lo) || d > static_cast<double>(hi)) {
      fail(path, number(d) + " is outside " + std::to_string(lo) + ".." + std::to_string(hi));
    }
    return static_cast<long long>(d);
  }
  std::vector<std::string> texts(const Value& v, const std::string& path) const {
    if (!v.has_list_value()) fail(path, "expected an array of strings, got " + kind_of(v));
    std::vector<std::string> out;
    for (int i = 0; i < v.list_value().values_size(); ++i) {
      out.push_back(text(v.list_value().values(i), path + "[" + std::to_string(i) + "]"));
    }
    return out;
  }
  // A file named relative to the bus file; it must exist.
  std::string file_name(const Value& v, const std::string& path) const {
    std::filesystem::path p(text(v, path));
    if (p.is_relative() && !dir_.empty()) p = std::filesystem::path(dir_) / p;
    return p.string();
  }
  std::string existing_file(const Value& v, const std::string& path) const {
    std::string name = file_name(v, path);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(name, ec)) fail(path, "no file " + name);
    return name;
  }
  // A JSON number as written for a person: 5, 2.5, 1e+300 (no undefined cast of a huge one).
  static std::string number(double d) {
    char b[32];
    std::snprintf(b, sizeof b, "%.15g", d);
    return b;
  }

 private:
  std::string file_;
  std::string dir_;
};

// The keys of a station, as the `rs4sim run` options without the dashes.
constexpr const char* kKeys[] = {"address", "device", "gsd", "modules", "ident", "cfg",
                                 "boot-time", "command-time", "adapter-response-time",
                                 "serial-number", "state", "rs232", "pc-adapter", "f-dest-add"};
// The byte devices' options: those devices are not DP stations.
constexpr const char* kByteKeys[] = {"baud", "format", "elements", "beams", "model",
                                     "mode", "blocked", "door", "node"};

// Refuses a key no station takes (the byte devices' options with their own reason).
void check_keys(const Reader& r, const std::vector<std::string>& keys, const std::string& path) {
  for (const auto& key : keys) {
    const std::string at = json::member_path(path, key);
    if (std::find(std::begin(kByteKeys), std::end(kByteKeys), key) != std::end(kByteKeys)) {
      r.fail(at, "an option of the RS-485 byte devices, which are not DP stations and cannot "
                 "be on a DP bus");
    }
    if (std::find(std::begin(kKeys), std::end(kKeys), key) == std::end(kKeys)) {
      std::string known;
      for (const char* k : kKeys) known += (known.empty() ? "" : ", ") + std::string(k);
      r.fail(at, "unknown key (a station takes: " + known + ")");
    }
  }
}

// One key's value into the station (a known key: check_keys came first).
void read_key(const Reader& r, const std::string& key, const Value& x, const std::string& at,
              BusStation& s) {
  DeviceOptions& o = s.options;
  if (key == "address") {
    // a slave in operation: 0..125, as `run --address` [docs/decisions.md#rs4-address-126]
    o.address = static_cast<int>(r.integer(x, at, 0, dp::pdu::sap::kMaxSlaveAddress));
  }
  if (key == "device") s.device = r.text(x, at);
  if (key == "gsd") o.gsd = r.existing_file(x, at);
  if (key == "modules") o.modules = r.texts(x, at);
  if (key == "ident") o.ident = r.text(x, at);
  if (key == "cfg") o.cfg = r.text(x, at);
  if (key == "boot-time") o.boot_time_ms = static_cast<int>(r.integer(x, at, 0, 3'600'000));
  if (key == "command-time") o.command_time_ms = static_cast<int>(r.integer(x, at, 0, 120'000));
  if (key == "adapter-response-time") {
    o.response_time_ms = static_cast<int>(r.integer(x, at, 0, 1000));
  }
  if (key == "serial-number") o.serial_numbers = {r.integer(x, at, 1, 4'294'967'295LL)};
  if (key == "state") o.state_files = {r.file_name(x, at)};
  if (key == "rs232") o.rs232 = r.text(x, at);
  if (key == "pc-adapter") o.pc_adapter = r.text(x, at);
  if (key == "f-dest-add") o.f_dest_add = static_cast<int>(r.integer(x, at, 1, 65534));
}

// The station's device: given, or "generic" for a slave from its GSD or ident; one that can be
// on a DP bus.
void check_device(const Reader& r, BusStation& s, const std::string& path) {
  const DeviceOptions& o = s.options;
  if (s.device.empty()) {
    if (o.gsd.empty() && o.ident.empty()) {
      r.fail(path, "\"device\" is missing (or give \"gsd\" for a slave from its GSD file)");
    }
    s.device = "generic";
  }
  const DeviceEntry* entry = find_device(s.device);
  if (entry == nullptr) {
    std::string names;
    for (const auto& n : device_names()) names += (names.empty() ? "" : ", ") + n;
    r.fail(path + ".device",
           "no device \"" + json::cut(s.device) + "\" (devices: " + names + ")");
  }
  if (entry->byte_device || !entry->simulate) {
    r.fail(path + ".device",
           "\"" + json::cut(s.device) + "\" is not a DP station and cannot be on a DP bus");
  }
  s.kind = entry->kind;
}

BusStation read_station(const Reader& r, const Value& v, const std::string& path) {
  if (!v.has_struct_value()) r.fail(path, "expected an object, got " + kind_of(v));
  const auto& fields = v.struct_value().fields();
  std::vector<std::string> keys;
  for (const auto& [k, value] : fields) keys.push_back(k);
  std::sort(keys.begin(), keys.end());  // the first refused key does not depend on map order
  check_keys(r, keys, path);
  BusStation s;
  s.path = path;
  for (const auto& key : keys) read_key(r, key, fields.at(key), json::member_path(path, key), s);
  if (!s.options.address) r.fail(path, "\"address\" is missing");
  check_device(r, s, path);
  return s;
}

}  // namespace

BusFile parse_bus_file(const std::string& text, const std::string& file, const std::string& dir,
                       const std::string& link_baud) {
  Reader r(file, dir);
  Value root;
  const auto status = json::to_message(text, root, {});
  if (!status.ok()) {
    // file:line:column of the first break of the grammar; protobuf's reason where the text is
    // JSON its parser still refuses (a number beyond double, say).
    if (const auto syntax = json::first_syntax_error(text)) {
      throw UsageError(file + ":" + json::line_column(text, syntax->offset) +
                       ": not valid JSON: " + syntax->reason);
    }
    r.fail("$", "not valid JSON: " + std::string(status.message()));
  }
  if (!root.has_struct_value()) r.fail("$", "expected an object {\"stations\": [...]}");
  for (const auto& [key, value] : root.struct_value().fields()) {
    if (key != "stations") r.fail(json::member_path("$", key), "unknown key (the bus file takes: stations)");
  }
  const auto it = root.struct_value().fields().find("stations");
  if (it == root.struct_value().fields().end()) r.fail("$", "\"stations\" is missing");
  if (!it->second.has_list_value() || it->second.list_value().values_size() == 0) {
    r.fail("$.stations", "expected a non-empty array of stations");
  }
  BusFile bus;
  bus.file = file;
  std::map<int, std::string> used;  // address → path
  std::string rs232;                 // the station that serves the RS232 port
  const auto& list = it->second.list_value();
  for (int i = 0; i < list.values_size(); ++i) {
    const std::string path = "$.stations[" + std::to_string(i) + "]";
    BusStation s = read_station(r, list.values(i), path);
    const int a = *s.options.address;
    if (const auto u = used.find(a); u != used.end()) {
      r.fail(path + ".address", std::to_string(a) + " is already used by " + u->second);
    }
    used.emplace(a, path);
    if (!s.options.rs232.empty()) {
      if (!rs232.empty()) {
        r.fail(path + ".rs232", "one station of a bus serves its RS232 port (" + rs232 +
                                    " does already)");
      }
      rs232 = path;
    }
    s.options.link_baud = link_baud;
    try {
      find_device(s.device)->validate(s.options);
    } catch (const UsageError& e) {
      r.fail(path, e.what());
    }
    bus.stations.push_back(std::move(s));
  }
  return bus;
}

BusFile read_bus_file(const std::string& file, const std::string& link_baud) {
  const auto text = read_whole_file(file);
  if (!text) throw UsageError(file + ": cannot read the bus file: " + text.error);
  return parse_bus_file(text.bytes, file, std::filesystem::path(file).parent_path().string(),
                        link_baud);
}

namespace {

// Every station's instance on one real-time link.
class BusInstance final : public DeviceInstance {
 public:
  explicit BusInstance(const BusFile& bus) : file_(bus.file) {
    for (const auto& s : bus.stations) {
      children_.push_back(find_device(s.device)->build(s.options));
    }
  }
  std::vector<dp::Station*> stations() override {
    std::vector<dp::Station*> all;
    for (auto& c : children_) {
      for (dp::Station* s : c->stations()) all.push_back(s);
    }
    return all;
  }
  void start(dp::TimePoint now) override {
    for (auto& c : children_) c->start(now);
  }
  [[nodiscard]] std::string describe() const override {
    std::string d = "bus " + file_ + " (" + std::to_string(children_.size()) + " stations: ";
    for (std::size_t i = 0; i < children_.size(); ++i) {
      d += (i ? "; " : "") + children_[i]->describe();
    }
    return d + ")";
  }
  void print_status(std::ostream& out, const dp::link::StationCounters& link) const override {
    out << "link: telegrams received " << link.received << ", sent " << link.sent
        << ", malformed " << link.malformed << ", link errors " << link.send_errors << std::endl;
    for (const auto& c : children_) c->print_status(out, link);
  }
  // The one RS232 port a bus may serve (parse_bus_file refuses a second).
  std::optional<SidePort> side_port() override {
    for (auto& c : children_) {
      if (auto side = c->side_port()) return side;
    }
    return std::nullopt;
  }
  void on_user_signal(bool second, dp::TimePoint now) override {
    for (auto& c : children_) c->on_user_signal(second, now);
  }
  // One set of services for every station: Device, Observation, Faults, SimTime over the
  // RS4s (one target, one event stream that also watches the GSD stations) and GsdStations
  // over the GSD stations.
  ServiceList services(const ServiceContext& c) override {
    const Served all = served(children_);
    target_ = std::make_unique<rpc::DeviceTarget>(all.rs4s, c.clock, c.io);
    target_->set_link_timing(c.turnaround, c.slot_time_us);
    target_->set_other_stations(all.others);
    target_->route_pc_adapter(all.pc_adapter);
    rpc::EventHub* hub = target_->events();
    for (const GsdStation* g : all.gsd) hub->watch(rpc::gsd_watcher(*g));
    for (rpc::TappedStation* t : all.taps) t->set_hub(hub);
    ServiceList list = rpc::rs4_service_set(*target_, c.executor, all.gsd);
    if (!all.gsd.empty()) {
      const dp::Clock& clock = c.clock;
      rpc::GsdServiceContext g{c.executor, all.gsd, [hub, &clock] { hub->poll(clock.now()); }};
      g.turnaround = c.turnaround;
      g.slot_time_us = c.slot_time_us;
      list.push_back(std::make_shared<rpc::GsdStationsService>(std::move(g)));
    }
    return list;
  }
  void stop_services() override {
    if (target_) target_->stop();
  }

 private:
  // Every child's ServedStations gathered for one target.
  struct Served {
    std::vector<rpc::DeviceTarget::Station> rs4s;
    std::vector<GsdStation*> gsd;
    std::map<std::uint8_t, std::string> others;
    std::vector<rpc::TappedStation*> taps;
    rpc::DeviceTarget::PcAdapterHook pc_adapter;
  };
  static Served served(const std::vector<std::unique_ptr<DeviceInstance>>& children) {
    Served all;
    // The RS4 → its instance's hook (the one with the RS232 port routes through it).
    auto hooks = std::make_shared<std::map<const rs4::device::Rs4Device*,
                                           decltype(ServedStations::pc_adapter)>>();
    for (const auto& c : children) {
      ServedStations s = c->served_stations();
      for (const auto& r : s.rs4s) {
        all.rs4s.push_back({r.address, r.device});
        if (s.pc_adapter) (*hooks)[r.device] = s.pc_adapter;
      }
      for (GsdStation* g : s.gsd) {
        all.gsd.push_back(g);
        all.others.emplace(g->address(), kGsdStationKind);
      }
      for (const auto& o : s.others) all.others.emplace(o.address, o.what);
      all.taps.insert(all.taps.end(), s.taps.begin(), s.taps.end());
    }
    all.pc_adapter = [hooks](rs4::device::Rs4Device& device, bool attached, dp::TimePoint now) {
      if (const auto it = hooks->find(&device); it != hooks->end()) {
        it->second(device, attached, now);
      } else {
        attached ? device.adapter().attach_pc_adapter(now)
                 : device.adapter().detach_pc_adapter(now);
      }
    };
    return all;
  }

  std::string file_;
  std::vector<std::unique_ptr<DeviceInstance>> children_;
  std::unique_ptr<rpc::DeviceTarget> target_;
};

bool is_gsd_station(const BusStation& s) {
  return !s.options.gsd.empty() && s.kind == stream::DeviceKind::kGeneric;
}

// The GSD stations as our master configures them: the file's "f-dest-add" is known to both
// ends of the line (`rs4sim master --bus-file` reads the same file), so our F-host sends it.
std::vector<GsdStationSpec> hosted_gsd_stations(const BusFile& bus) {
  std::vector<GsdStationSpec> specs;
  for (const auto& s : bus.stations) {
    if (!is_gsd_station(s)) continue;
    const DeviceOptions& o = s.options;
    specs.push_back(load_gsd_station(o.gsd, o.modules, *o.address));
    if (o.f_dest_add) specs.back().f_dest_add = check_f_dest_add(specs.back(), *o.f_dest_add);
  }
  return specs;
}

// The master's entry for a station that is not a GSD station.
dp::master::SlaveEntry master_entry(const BusStation& s) {
  const DeviceOptions& o = s.options;
  if (s.kind == stream::DeviceKind::kGeneric) {
    return dp::devices::master_entry_for(generic_slave_config(*o.address, o.ident, o.cfg));
  }
  rs4::device::Rs4MasterOptions r;
  r.address = static_cast<std::uint8_t>(*o.address);
  std::shared_ptr<const gsd::Device> file;  // an RS4 with "gsd": configured from that file
  if (!o.gsd.empty()) {
    const auto spec = load_gsd_station(o.gsd, o.modules, *o.address);
    file = spec.device;
    r.device = file.get();
    r.module = spec.setup.modules.front();
  }
  auto e = rs4::device::rs4_master_entry(r);
  if (!e) throw UsageError(s.path + ": " + e.error().what());
  return e.value().slave;
}

// Every station with our master on the in-memory bus.
class BusSegment final : public SimulatedSegment {
 public:
  explicit BusSegment(const BusFile& bus)
      : f_hosts_(std::make_unique<gsd::GsdMasterSlaves>(hosted_gsd_stations(bus))) {
    dp::master::MasterConfig m;
    const std::string baud = bus.stations.front().options.link_baud;
    m.bus = dp::master::BusParameters::defaults_for(*dp::parse_baud_rate(baud));
    std::vector<std::uint8_t> addresses;
    for (const auto& s : bus.stations) {
      addresses.push_back(static_cast<std::uint8_t>(*s.options.address));
      if (!is_gsd_station(s)) {
        m.slaves.push_back(master_entry(s));
        continue;
      }
      const GsdStationSpec& spec = f_hosts_->find(addresses.back())->spec;  // F-blocks written
      if (const auto t = gsd_max_tsdr(spec, baud)) fit_max_tsdr(m.bus, *t);
      m.slaves.push_back(gsd_master_entry(spec, std::chrono::milliseconds(100)));
    }
    m.address = free_master_address(addresses);
    master_address_ = m.address;
    bus_ = std::make_unique<dp::link::MemoryBus>(clock_);
    master_ = std::make_unique<dp::master::Master>(m);
    bus_->attach(*master_);
    for (const auto& s : bus.stations) {
      children_.push_back(find_device(s.device)->build(s.options));
      children_.back()->start(clock_.now());
      for (dp::Station* st : children_.back()->stations()) bus_->attach(*st);
    }
    addresses_ = addresses;
    bus_->start();
  }
  void run_for(dp::Duration d) override {
    bus_->run_until([] { return false; }, clock_.now() + d, [this] { drain(); });
  }
  [[nodiscard]] std::uint8_t master_address() const override { return master_address_; }
  [[nodiscard]] std::size_t in_data_exchange() const {
    return static_cast<std::size_t>(std::count_if(addresses_.begin(), addresses_.end(), [&](auto a) {
      return master_->poll_state(a) == dp::master::PollState::kDataExchange;
    }));
  }
  void print_summary(std::ostream& out) const override {
    out << ": " << master_->counters().cycles << " cycles, " << in_data_exchange() << " of "
        << addresses_.size() << " stations in data exchange" << std::endl;
    for (std::size_t i = 0; i < children_.size(); ++i) {
      children_[i]->print_status(out, bus_->counters(addresses_[i]));
    }
  }
  [[nodiscard]] bool healthy() const override { return in_data_exchange() == addresses_.size(); }
  dp::link::MemoryBus* bus() override { return bus_.get(); }
  // As BusInstance's, on this segment's manual clock (SimTime moves it; the bus faults act on
  // its bus). The GSD stations' F-modules have our master's F-hosts (GsdStations.AcknowledgeF
  // acknowledges); the RS4s here run without an F-host (docs/gsd.md "Bus file").
  ServiceList services(const ServiceContext& c) override {
    ServedStations all;
    for (const auto& child : children_) {
      ServedStations s = child->served_stations();
      all.rs4s.insert(all.rs4s.end(), s.rs4s.begin(), s.rs4s.end());
      all.gsd.insert(all.gsd.end(), s.gsd.begin(), s.gsd.end());
      all.others.insert(all.others.end(), s.others.begin(), s.others.end());
    }
    const std::vector<GsdStation*> gsd = all.gsd;
    target_ = std::make_unique<MemoryBusTarget>(
        clock_, *bus_, [this] { drain(); }, std::move(all));
    ServiceList list = rpc::rs4_service_set(*target_, c.executor, gsd);
    if (!gsd.empty()) {
      rpc::EventHub* hub = target_->events();
      watch_f_hosts(*hub, gsd, *f_hosts_);
      rpc::GsdServiceContext g{c.executor, gsd, [hub, this] { hub->poll(clock_.now()); },
                               bus_.get()};
      g.f_hosts = f_hosts_.get();
      list.push_back(std::make_shared<rpc::GsdStationsService>(std::move(g)));
    }
    return list;
  }

 private:
  void drain() { drain_with_f_hosts(*master_, events_, *f_hosts_, clock_.now()); }

  // Our master's F-host for every F-module of the GSD stations (docs/profisafe.md).
  std::unique_ptr<gsd::GsdMasterSlaves> f_hosts_;
  dp::ManualClock clock_;
  std::unique_ptr<dp::link::MemoryBus> bus_;
  std::unique_ptr<dp::master::Master> master_;
  std::vector<std::unique_ptr<DeviceInstance>> children_;
  std::vector<std::uint8_t> addresses_;
  std::uint8_t master_address_ = 1;
  std::vector<dp::master::MasterEvent> events_;
  std::unique_ptr<MemoryBusTarget> target_;  // made by services(); the bus observes for it
};

}  // namespace

DeviceEntry bus_device_entry(BusFile bus) {
  double simulated = 1;
  for (const auto& s : bus.stations) {
    simulated = std::max(simulated, find_device(s.device)->simulated_seconds);
  }
  auto shared = std::make_shared<const BusFile>(std::move(bus));
  return {
      "bus",
      simulated,
      [](DeviceOptions&) {},  // every station was validated by read_bus_file
      [shared](const DeviceOptions&) { return std::make_unique<BusInstance>(*shared); },
      [shared](const DeviceOptions&) { return std::make_unique<BusSegment>(*shared); },
      {},
  };
}

}  // namespace rs4sim::app
