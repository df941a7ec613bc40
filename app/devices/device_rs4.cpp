// Device entry `rs4` (the default): one emulated RS4/PROFIsafe (rs4/device), its ident,
// F_Dest_Add rule and slave settings from the built-in GSD (rs4/adapter/rs4_gsd.h). On a
// real-time link `--address` may repeat: one RS4 per address, each its own station on the
// same line (a machine's 2..4 scanners on one PROFIBUS), served by one gRPC target.
#include "app/demos/demos.h"
#include "app/devices/device_options.h"
#include "app/devices/device_registry.h"
#include "app/devices/gsd_station_file.h"
#include "app/devices/rs4_state_file.h"
#include "app/runtime/run_options.h"
#include "dp/pdu/sap.h"
#include "rpc/device_target.h"
#include "rpc/rs4_services.h"
#include "rpc/segment_target.h"
#include "rpc/tapped_station.h"
#include "rs4/adapter/rs4_gsd.h"
#include "rs4/device/description.h"
#include "rs4/device/rs4_segment.h"
#include "rs4/rs232/rs232_port.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <ostream>
#include <vector>

namespace rs4sim::app {
namespace {

using rs4::device::Rs4Device;
using rs4::device::Rs4DeviceConfig;

Rs4DeviceConfig device_config(const DeviceOptions& o, int address, std::size_t index) {
  Rs4DeviceConfig c;
  if (index < o.serial_numbers.size()) {
    c.scanner.identity.serial_number = static_cast<std::uint32_t>(o.serial_numbers[index]);
  }
  c.switches = rs4::device::switches_for(static_cast<std::uint8_t>(address));
  c.boot_time = std::chrono::milliseconds(*o.boot_time_ms);
  c.adapter.rs4_command_time = std::chrono::milliseconds(*o.command_time_ms);
  c.adapter.response_time = std::chrono::milliseconds(*o.response_time_ms);
  return c;
}

// Every --address of the run, in the order given.
std::vector<int> all_addresses(const DeviceOptions& o) {
  std::vector<int> all{*o.address};
  all.insert(all.end(), o.more_addresses.begin(), o.more_addresses.end());
  return all;
}

std::string joined_numbers(const std::vector<int>& numbers) {
  std::string s;
  for (const int n : numbers) s += (s.empty() ? "" : ", ") + std::to_string(n);
  return s;
}

// --rs232 pty | serial:DEVICE[@BAUD] → the serial device ("" for a pty) and the port's options.
struct Rs232Choice {
  std::string path;
  rs4::rs232::PortOptions options;
};

Rs232Choice rs232_choice(const std::string& spec) {
  Rs232Choice c;
  if (spec == "pty") return c;
  constexpr std::string_view kSerial = "serial:";
  if (spec.rfind(kSerial, 0) != 0 || spec.size() == kSerial.size()) {
    throw UsageError("--rs232 " + spec +
                     ": use pty or serial:DEVICE[@BAUD], e.g. serial:/dev/ttyUSB1@57600");
  }
  std::string rest = spec.substr(kSerial.size());
  if (const auto at = rest.find('@'); at != std::string::npos) {
    const std::string baud = rest.substr(at + 1);
    c.options.baud = parse_bit_rate(baud);
    rest = rest.substr(0, at);
  }
  c.path = rest;
  if (const auto why = c.options.validate()) throw UsageError("--rs232 " + spec + ": " + *why);
  return c;
}

// --state FILE of the RS4 at `address` (index `index` of --address), or nullptr. The unit it
// describes must be the one the options name: its switches give `address`, its serial number
// is --serial-number's when one is given.
std::unique_ptr<Rs4StateFile> state_file(const DeviceOptions& o, int address, std::size_t index) {
  if (index >= o.state_files.size()) return nullptr;
  auto file = std::make_unique<Rs4StateFile>(o.state_files[index]);
  if (const auto& s = file->loaded()) {
    const auto at = rs4::adapter::station_address(s->switches);
    if (!at || at.value() != address) {
      throw std::runtime_error(
          "state file " + file->path() + ": the unit's address switches are set to " +
          (at ? "station " + std::to_string(at.value()) : std::string("an invalid address")) +
          " (changed through SetAddressSwitches); run it with --address " +
          (at ? std::to_string(at.value()) : std::string("after correcting the switches")));
    }
    if (index < o.serial_numbers.size() &&
        static_cast<long long>(s->set.identity.serial_number) != o.serial_numbers[index]) {
      throw std::runtime_error("state file " + file->path() + " is the memory of unit " +
                               std::to_string(s->set.identity.serial_number) +
                               "; --serial-number " + std::to_string(o.serial_numbers[index]) +
                               " names another unit (a new unit starts with a new state file)");
    }
  }
  return file;
}

// --gsd FILE [--module NAME]: the RS4 as the user's GSD describes it (its ident, Chk_Cfg and
// User_Prm_Data layout; docs/gsd.md "The RS4 from your GSD"); nullopt without --gsd.
// UsageError naming the file and what does not fit the RS4.
struct UserGsd {
  std::shared_ptr<const gsd::Device> device;
  std::shared_ptr<const rs4::adapter::GsdProfile> profile;
};

std::optional<UserGsd> user_gsd(const DeviceOptions& o,
                                std::vector<std::string>* warnings = nullptr) {
  if (o.gsd.empty()) return std::nullopt;
  if (o.modules.size() > 1) {
    throw UsageError("--module: the RS4/PROFIsafe is one module; name it once");
  }
  const GsdStationSpec spec = load_gsd_station(o.gsd, o.modules, *o.address, warnings);
  check_gsd_baud(spec, o.link_baud);
  auto p = rs4::adapter::gsd_profile(*spec.device, o.modules.empty() ? "" : o.modules.front(),
                                     o.gsd);
  if (!p) throw UsageError(p.error().what());
  return UserGsd{spec.device,
                 std::make_shared<const rs4::adapter::GsdProfile>(std::move(p).value())};
}

Rs4DeviceConfig unit_config(const DeviceOptions& o, int address, std::size_t index,
                            const Rs4StateFile* file, const std::optional<UserGsd>& gsd) {
  auto c = device_config(o, address, index);
  if (file != nullptr && file->loaded()) c = rs4::device::with_state(c, *file->loaded());
  if (gsd) c.adapter.gsd = gsd->profile;
  return c;
}

void print_state(std::ostream& out, const Rs4Device& d) {
  const auto v = d.adapter().view();
  out << "rs4 " << int(d.address()) << ": LED " << rs4::adapter::to_string(v.led) << ", RS4 "
      << rs4::scanner::to_string(v.rs4) << ", input byte " << hex(std::span(&v.input_byte, 1))
      << ", output byte " << hex(std::span(&v.output_byte, 1)) << ", PROFIsafe "
      << profisafe::to_string(v.fdevice) << std::endl;
}

// The RS4s of a real-time run: one Rs4Device and TappedStation per --address. The RS232
// port (--rs232) is the only RS4's (validate() refuses it with several).
class Rs4Instance final : public DeviceInstance {
 public:
  explicit Rs4Instance(const DeviceOptions& o)
      : boot_time_ms_(*o.boot_time_ms), attached_at_start_(o.pc_adapter == "attached") {
    const auto addresses = all_addresses(o);
    const auto gsd = user_gsd(o);
    for (std::size_t i = 0; i < addresses.size(); ++i) {
      auto file = state_file(o, addresses[i], i);
      rs4s_.push_back(std::make_unique<Rs4>(unit_config(o, addresses[i], i, file.get(), gsd),
                                            static_cast<std::uint8_t>(addresses[i]),
                                            std::move(file)));
    }
    if (!o.rs232.empty()) {
      auto choice = rs232_choice(o.rs232);
      rs232_path_ = choice.path;
      port_.emplace(rs4s_.front()->device.adapter(), choice.options);
    }
  }
  std::vector<dp::Station*> stations() override {
    std::vector<dp::Station*> out;
    for (const auto& r : rs4s_) {
      out.push_back(r->kept ? static_cast<dp::Station*>(&*r->kept) : &r->tap);
    }
    return out;
  }
  std::optional<SidePort> side_port() override {
    if (!port_) return std::nullopt;
    return SidePort{"rs232", &*port_, rs232_path_};
  }
  Rs4Instance(const Rs4Instance&) = delete;
  Rs4Instance& operator=(const Rs4Instance&) = delete;
  ~Rs4Instance() override {
    for (const auto& r : rs4s_) {
      if (r->state) r->state->keep(r->device);  // what changed since the last link call
    }
  }
  void start(dp::TimePoint now) override {
    for (const auto& r : rs4s_) {
      if (r->state && r->state->loaded() &&
          !rs4::device::restore_state(r->device, *r->state->loaded(), now)) {
        throw std::runtime_error("state file " + r->state->path() +
                                 ": the RS4 refused the parameter set in it");
      }
      r->device.power_on(now);
      if (attached_at_start_) attach(r->device, true, now);
    }
  }
  // SIGUSR1/SIGUSR2: the PC adapter at every RS4 of the run (Device.SetPcAdapter: one).
  void on_user_signal(bool second, dp::TimePoint now) override {
    for (const auto& r : rs4s_) attach(r->device, !second, now);
    std::cerr << "rs4sim: PC adapter " << (second ? "removed" : "attached")
              << (rs4s_.size() > 1 ? " (every RS4: " + joined_numbers(addresses()) + ")" : "")
              << std::endl;
  }
  [[nodiscard]] std::string describe() const override {
    const auto& gsd = rs4s_.front()->device.adapter().gsd();
    char ident[8];
    std::snprintf(ident, sizeof ident, "%x", gsd.slave.ident_number);
    std::string f_dest;
    for (const auto& r : rs4s_) {
      f_dest += (f_dest.empty() ? "" : ", ") + std::to_string(rs4::adapter::f_dest_add(r->address));
    }
    const bool one = rs4s_.size() == 1;
    return (one ? "RS4/PROFIsafe at address "
                : std::to_string(rs4s_.size()) + " RS4/PROFIsafe at addresses ") +
           joined_numbers(addresses()) + " (ident 0x" + ident + ", F_Dest_Add " + f_dest +
           ", boot " + std::to_string(boot_time_ms_) + " ms" +
           (gsd.file == rs4::adapter::builtin_profile().file ? std::string()
                                                             : ", GSD " + gsd.file) +
           ")";
  }
  void print_status(std::ostream& out, const dp::link::StationCounters& link) const override {
    (void)link;
    for (const auto& r : rs4s_) print_state(out, r->device);
    if (port_) {
      const auto& k = port_->counters();
      out << "rs4 " << int(rs4s_.front()->address) << " RS232: commands " << k.commands
          << ", 0x23 sent " << k.measurements << ", refused (password) " << k.wrong_passwords
          << ", framing errors " << k.framing_errors << ", ignored while detached "
          << k.ignored_while_detached << std::endl;
    }
  }
  ServiceList services(const ServiceContext& c) override {
    std::vector<rpc::DeviceTarget::Station> stations;
    for (const auto& r : rs4s_) stations.push_back({r->address, &r->device});
    target_ = std::make_unique<rpc::DeviceTarget>(std::move(stations), c.clock, c.io);
    target_->set_link_timing(c.turnaround, c.slot_time_us);
    target_->route_pc_adapter([this](Rs4Device& device, bool attached, dp::TimePoint now) {
      attach(device, attached, now);
    });
    for (const auto& r : rs4s_) r->tap.set_hub(target_->events());
    return rpc::rs4_service_set(*target_, c.executor);
  }
  void stop_services() override {
    if (target_) target_->stop();
  }
  ServedStations served_stations() override {
    ServedStations s;
    for (const auto& r : rs4s_) {
      s.rs4s.push_back({r->address, &r->device});
      s.taps.push_back(&r->tap);
    }
    s.pc_adapter = [this](Rs4Device& device, bool attached, dp::TimePoint now) {
      attach(device, attached, now);
    };
    return s;
  }

 private:
  struct Rs4 {
    Rs4(const Rs4DeviceConfig& config, std::uint8_t a, std::unique_ptr<Rs4StateFile> file)
        : device(config), address(a), state(std::move(file)) {
      if (state) kept.emplace(tap, device, *state);
    }
    Rs4Device device;
    rpc::TappedStation tap{device};  // telegrams for the event stream
    std::uint8_t address;
    std::unique_ptr<Rs4StateFile> state;  // --state
    std::optional<KeptStation> kept;      // in front of `tap` with --state
  };

  [[nodiscard]] std::vector<int> addresses() const {
    std::vector<int> out;
    for (const auto& r : rs4s_) out.push_back(r->address);
    return out;
  }

  // The reed contact of the optical window: through the RS232 port when it is served (it
  // opens and closes with it; the port is the first RS4's), else the adapter alone.
  void attach(Rs4Device& device, bool attached, dp::TimePoint now) {
    if (port_ && &device == &rs4s_.front()->device) {
      attached ? port_->attach(now) : port_->detach(now);
    } else {
      attached ? device.adapter().attach_pc_adapter(now) : device.adapter().detach_pc_adapter(now);
    }
  }

  std::vector<std::unique_ptr<Rs4>> rs4s_;  // stable addresses: the stations point into them
  std::unique_ptr<rpc::DeviceTarget> target_;
  int boot_time_ms_;
  bool attached_at_start_;
  std::string rs232_path_;
  std::optional<rs4::rs232::Rs232Port> port_;
};

// Our master configured from the GSD and a PROFIsafe F-host that acknowledges every
// ACK_REQ, on the in-memory bus.
class Rs4Simulation final : public SimulatedSegment {
 public:
  explicit Rs4Simulation(const DeviceOptions& o)
      : gsd_(user_gsd(o)),
        state_(state_file(o, *o.address, 0)),
        segment_(segment_config(o, state_.get(), gsd_)) {
    if (state_) {
      if (state_->loaded() &&
          !rs4::device::restore_state(segment_.device(), *state_->loaded(), segment_.now())) {
        throw std::runtime_error("state file " + state_->path() +
                                 ": the RS4 refused the parameter set in it");
      }
      // Kept after every master cycle, whoever moves the time (run_for, the API's SimTime).
      segment_.set_observer([this](const dp::master::MasterEvent& e) {
        if (std::holds_alternative<dp::master::CycleCompleted>(e)) state_->keep(segment_.device());
      });
    }
    segment_.power_on();
  }
  Rs4Simulation(const Rs4Simulation&) = delete;
  Rs4Simulation& operator=(const Rs4Simulation&) = delete;
  ~Rs4Simulation() override {
    if (state_) state_->keep(segment_.device());
  }
  void run_for(dp::Duration d) override { segment_.run_for(d); }
  [[nodiscard]] std::uint8_t master_address() const override { return segment_.master().address(); }
  void print_summary(std::ostream& out) const override {
    out << " (from the GSD), F-host " << profisafe::to_string(segment_.fhost().state()) << ", "
        << segment_.master().counters().cycles << " cycles" << std::endl;
    print_state(out, segment_.device());
  }
  [[nodiscard]] bool healthy() const override { return segment_.in_data_exchange(); }
  dp::link::MemoryBus* bus() override { return &segment_.bus(); }
  ServiceList services(const ServiceContext& c) override {
    target_ = std::make_unique<rpc::SegmentTarget>(segment_);
    return rpc::rs4_service_set(*target_, c.executor);
  }

 private:
  // With --gsd our master is configured from the user's file too, as the PLC project is.
  static rs4::device::Rs4SegmentConfig segment_config(const DeviceOptions& o,
                                                      const Rs4StateFile* file,
                                                      const std::optional<UserGsd>& gsd) {
    rs4::device::Rs4SegmentConfig c;
    c.device = unit_config(o, *o.address, 0, file, gsd);
    c.master.address = static_cast<std::uint8_t>(*o.address);
    if (gsd) {
      c.master.device = gsd->device.get();
      c.master.module = gsd->profile->module;
    }
    c.master_address = *o.address == 1 ? 2 : 1;
    c.auto_ack_rei = true;
    // Nothing takes the segment's master events in a run (the API reads the device, the
    // event stream watches the bus): keeping them grew memory with simulated time.
    c.keep_events = false;
    return c;
  }

  std::optional<UserGsd> gsd_;            // --gsd
  std::unique_ptr<Rs4StateFile> state_;  // --state
  rs4::device::Rs4Segment segment_;
  std::unique_ptr<rpc::SegmentTarget> target_;
};

// The checks are the RS4's own (rs4/device/description.h); here the flags go in and the
// defaults come back, and the files (--rs232's port, --gsd) are opened.
void validate(DeviceOptions& o) {
  if (!o.ident.empty() || !o.cfg.empty()) {
    throw UsageError("--ident/--cfg are for --device generic; the RS4's come from its GSD");
  }
  refuse_unused(o, "rs4", rs4::device::description().options);
  if (!o.rs232.empty()) (void)rs232_choice(o.rs232);
  rs4::device::RunOptions r{.addresses = {},
                            .serial_numbers = o.serial_numbers,
                            .state_files = o.state_files,
                            .boot_time_ms = o.boot_time_ms,
                            .command_time_ms = o.command_time_ms,
                            .response_time_ms = o.response_time_ms,
                            .rs232 = !o.rs232.empty(),
                            .gsd = !o.gsd.empty(),
                            .module = !o.modules.empty()};
  // --address repeated: the first is the default address when only the others are set
  if (!o.address && !o.more_addresses.empty()) o.address = rs4::device::kDefaultAddress;
  if (o.address) r.addresses = all_addresses(o);
  if (const auto why = rs4::device::check_run_options(r); !why.empty()) throw UsageError(why);
  o.address = r.addresses.front();
  o.boot_time_ms = r.boot_time_ms;
  o.command_time_ms = r.command_time_ms;
  o.response_time_ms = r.response_time_ms;
  std::vector<std::string> warnings;
  (void)user_gsd(o, &warnings);  // the file's errors and what does not fit the RS4, now
  for (const auto& w : warnings) std::cerr << "warning: " << w << std::endl;
}

}  // namespace

DeviceEntry rs4_device_entry() {
  return {
      "rs4",
      40.0,
      validate,
      [](const DeviceOptions& o) { return std::make_unique<Rs4Instance>(o); },
      [](const DeviceOptions& o) {
        if (!o.more_addresses.empty()) {
          std::string slaves;
          for (const int a : all_addresses(o)) slaves += " --slave " + std::to_string(a);
          throw UsageError(
              "--link memory simulates one RS4 with our master; for several RS4s "
              "on the simulated bus use rs4sim master" +
              slaves + " --link memory (or run these on --link pty|serial|udp)");
        }
        return std::make_unique<Rs4Simulation>(o);
      },
      run_rs4_demo,
      false,
      rs4::device::description().options,
      rs4::device::description().kind,
  };
}

}  // namespace rs4sim::app
