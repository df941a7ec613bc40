#pragma once
// The device registry of the runtime: every device rs4sim emulates (`rs4`, `generic`, and
// later ones) has one DeviceEntry (app/devices/device_<name>.cpp), listed in
// device_registry.cpp (the line devices through the generated line_device_entries()). `rs4sim run` and `rs4sim demo` look devices
// up here and never name one: the Asio shell (app/runtime/shell.h) runs any entry on any link.
//
// An entry builds its station(s) from one validated DeviceOptions:
//   * for a real-time link (pty, serial, UDP): the device's own stations, talking to an
//     external master (DeviceInstance);
//   * for the in-memory link: the device with our class 1 master on a MemoryBus on the
//     manual clock (SimulatedSegment);
// and prints its status at the end of a run. Its narrated demo uses app/demos/narration.h.
//
// A byte device (GridScan, METRON, Polaris: DeviceEntry::byte_device) instead builds
// stream::ByteDevice cores (DeviceInstance::byte_devices()); the shell runs them with a
// stream::ByteRunner on pty/serial/UDP in their own LineSettings (serial: the port gets the
// device's format), and `--baud` reaches the entry as a plain bit rate (DeviceOptions::baud).

#include "app/demos/demos.h"
#include "dp/link/counters.h"
#include "dp/link/turnaround.h"
#include "dp/station.h"
#include "dp/time/clock.h"
#include "stream/byte_counters.h"
#include "stream/byte_device.h"
#include "stream/device_description.h"
#include "stream/frame_tap.h"

#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace grpc {
class Service;
}
namespace rs4sim::rpc {
class Executor;
class TappedStation;
}
namespace rs4sim::rs4::device {
class Rs4Device;
}
namespace rs4sim::gsd {
class GsdStation;
}
namespace boost::asio {
class io_context;
}

namespace rs4sim::app {

// The device options of `rs4sim run`, by name; an entry's validate() checks the ones it
// uses, refuses the others and fills its defaults.
// Unset options are nullopt/empty; app/devices/device_options.h refuses the ones an entry does not use.
struct DeviceOptions {
  std::optional<int> address;  // station address (rs4: the hex switches, default 4)
  // rs4: the second and further --address, each one more RS4 on the same link (DeviceFlag::
  // kAddresses; the other devices are one station and refuse it).
  std::vector<int> more_addresses;
  std::string ident;                    // generic: Ident_Number, e.g. "0x1234"
  std::string cfg;                      // generic: configuration identifiers in hex, e.g. "10 20"
  std::optional<int> boot_time_ms;      // rs4: boot until operational (default 30000)
  std::optional<int> command_time_ms;   // rs4: RS4 command processing (default 40)
  std::optional<int> response_time_ms;  // rs4: adapter response time (default 10)
  // Byte devices:
  std::optional<std::uint32_t> baud;        // --baud as bit/s (only for byte devices)
  std::string format;                       // --format, e.g. "8E1" (checked: stream::parse_format)
  std::optional<int> elements;              // --elements: element count (GridScan)
  std::optional<int> beams;                 // --beams: beam count (METRON, Polaris)
  std::string model;                        // --model
  std::string mode;                         // --mode
  std::optional<std::vector<int>> blocked;  // --blocked 9-13,25-34: sorted 1-based numbers
  std::optional<int> door;                  // --door N (GridScan: door position)
  std::optional<int> node;                  // --node N (METRON node)
  std::string wire_table;                   // --wire-table FILE (METRON byte values, JSON)
  std::string mains;                        // --mains on | off (GridScan: power at start)
  // The RS4's RS232 interface behind the optical PC adapter (docs/rs232.md):
  std::string rs232;       // --rs232 pty | serial:DEVICE[@BAUD]
  std::string pc_adapter;  // --pc-adapter attached | detached (at start)
  // rs4: --serial-number, one per --address in their order (the unit's identity; the
  // proxy tells units apart by it, [RS4 manual §7.1]); unnamed ones keep the default.
  std::vector<long long> serial_numbers;
  // rs4: --state FILE, one per --address in their order: the unit's non-volatile memory
  // (app/devices/rs4_state_file.h).
  std::vector<std::string> state_files;
  // generic: --gsd FILE, the device's GSD (app/devices/gsd_station_file.h), and --module NAME
  // in slot order (a compact station's one module is implicit).
  std::string gsd;
  std::vector<std::string> modules;
  // generic --gsd: --f-dest-add N, the F_Dest_Add of the station's PROFIsafe F-modules (their
  // address switch; default: the configuration's F_Dest_Add).
  std::optional<int> f_dest_add;
  // The PROFIBUS rate of the run (--baud of a DP link), for checking it against a GSD.
  std::string link_baud = "1.5M";
};

// A device's second serial port beside its main link (the RS4's RS232 interface): the shell
// opens it on a pseudo-terminal (the path goes out as "<name>: <path>", the second stdout
// line) or a serial device, and runs it with its own ByteRunner on the same loop.
struct SidePort {
  std::string name;  // "rs232"
  stream::ByteDevice* device = nullptr;
  std::string path;  // empty: a pseudo-terminal; else the serial device
};

// What a device needs to offer its gRPC services (docs/rpc.md): they reach its cores only
// through `executor` (the run's loop); `io` and `clock` are the loop's, for timers.
struct ServiceContext {
  rpc::Executor& executor;
  boost::asio::io_context& io;
  const dp::Clock& clock;
  // On a real-time PROFIBUS link: the replies' turnaround of the station at an address
  // (nullptr: none), read on the loop, and --tsl; empty/nullopt elsewhere.
  dp::link::TurnaroundSource turnaround = {};
  std::optional<std::int64_t> slot_time_us = std::nullopt;
};
using ServiceList = std::vector<std::shared_ptr<grpc::Service>>;

using gsd::GsdStation;

// What one instance contributes when a run serves several instances' stations under one set
// of services (a bus file, app/devices/bus_file.h): its RS4s, its GSD stations, the stations
// without an API of their own, and the taps that show the event stream their telegrams on a
// real-time link (the memory bus shows them all itself).
struct ServedStations {
  struct Rs4 {
    std::uint8_t address;
    rs4::device::Rs4Device* device;
  };
  struct Other {
    std::uint8_t address;
    std::string what;  // "a generic slave (no API of its own)"
  };
  std::vector<Rs4> rs4s;
  std::vector<GsdStation*> gsd;
  std::vector<Other> others;
  std::vector<rpc::TappedStation*> taps;
  // Device.SetPcAdapter for one of `rs4s` (the RS4 whose RS232 port is served routes it
  // through the port); empty: the adapter alone.
  std::function<void(rs4::device::Rs4Device&, bool attached, dp::TimePoint)> pc_adapter = {};
};

// One device built for a real-time link.
class DeviceInstance {
 public:
  virtual ~DeviceInstance() = default;
  // The stations the link runs (they live as long as this object).
  [[nodiscard]] virtual std::vector<dp::Station*> stations() { return {}; }
  // A byte device's cores (non-empty: the shell runs a stream::ByteRunner with them instead
  // of a StationRunner, in the first one's LineSettings); they live as long as this object.
  [[nodiscard]] virtual std::vector<stream::ByteDevice*> byte_devices() { return {}; }
  // The protocol on the byte devices' line, named in every record of its --capture.
  [[nodiscard]] virtual stream::LineProtocol line_protocol() const {
    return stream::LineProtocol::kRaw;
  }
  // The second port, if the options asked for one.
  [[nodiscard]] virtual std::optional<SidePort> side_port() { return std::nullopt; }
  // SIGUSR1 (`second` false) / SIGUSR2 while running (the RS4: the PC adapter attached /
  // removed).
  virtual void on_user_signal(bool second, dp::TimePoint now) { (void)second, (void)now; }
  // Called once before the link starts (e.g. the RS4's power-on).
  virtual void start(dp::TimePoint now) { (void)now; }
  // "generic slave 5 (ident 0x1234, cfg 10 20)": the banner line names the device.
  [[nodiscard]] virtual std::string describe() const = 0;
  // The status line(s) at the end of a run; `link` = the link's counters (a station
  // device's, then a byte device's).
  virtual void print_status(std::ostream& out, const dp::link::StationCounters& link) const {
    (void)out;
    (void)link;
  }
  virtual void print_byte_status(std::ostream& out, const stream::ByteCounters& link) const {
    (void)out;
    (void)link;
  }
  // The device's gRPC services (empty: the device has none yet); they live as long as this.
  virtual ServiceList services(const ServiceContext& context) {
    (void)context;
    return {};
  }
  // The server has shut down: the services end their timers on the loop, so that the loop
  // can finish.
  virtual void stop_services() {}
  // Its stations for a combined run's services (instead of services(); see ServedStations).
  virtual ServedStations served_stations() { return {}; }
};

// One device with our master on the in-memory bus (simulated time).
class SimulatedSegment {
 public:
  virtual ~SimulatedSegment() = default;
  virtual void run_for(dp::Duration d) = 0;
  [[nodiscard]] virtual std::uint8_t master_address() const = 0;
  // The rest of the summary line after "in-memory bus, N s simulated, master M", then
  // the device's status.
  virtual void print_summary(std::ostream& out) const = 0;
  // Exit code 0 when the device reached data exchange.
  [[nodiscard]] virtual bool healthy() const = 0;
  // The in-memory bus, for --capture (nullptr: none to observe).
  virtual dp::link::MemoryBus* bus() { return nullptr; }
  // A byte device's in-memory line, for --capture: installs `tap` on it (false: no line) and
  // names its protocol.
  virtual bool tap_line(stream::FrameTap tap) {
    (void)tap;
    return false;
  }
  [[nodiscard]] virtual stream::LineProtocol line_protocol() const {
    return stream::LineProtocol::kRaw;
  }
  // The gRPC services, with SimTime moving this segment's manual clock (empty: none yet).
  virtual ServiceList services(const ServiceContext& context) {
    (void)context;
    return {};
  }
};

struct DeviceEntry {
  std::string name;
  double simulated_seconds = 10;  // --link memory without --duration
  // Checks the options (UsageError with the reason) and fills the defaults.
  std::function<void(DeviceOptions&)> validate;
  std::function<std::unique_ptr<DeviceInstance>(const DeviceOptions&)> build;
  // Empty: no in-memory link (`--link memory` is refused).
  std::function<std::unique_ptr<SimulatedSegment>(const DeviceOptions&)> simulate;
  // The narrated demo on the simulated bus; returns the exit code. Empty: no demo.
  std::function<int(RunSession&, std::ostream&, const DemoOptions&)> demo;
  // A byte device: build() gives byte_devices(); --baud is a plain bit rate.
  bool byte_device = false;
  // The options it takes, from its description (stream/device_description.h): validate()
  // refuses the others, and `rs4sim run --help` shows their help.
  std::span<const stream::OptionInfo> options = {};
  // What it is (its description's kind): the code asks this, never the name.
  stream::DeviceKind kind = stream::DeviceKind::kRs4;
};

// Every device, in the order of device_registry.cpp.
const std::vector<DeviceEntry>& device_registry();
// nullptr for an unknown name.
const DeviceEntry* find_device(std::string_view name);
// The entry of a kind (every kind has one).
const DeviceEntry& find_device(stream::DeviceKind kind);
// "generic | rs4", for help texts.
std::vector<std::string> device_names();

// The entries (app/devices/device_<name>.cpp).
DeviceEntry rs4_device_entry();
DeviceEntry generic_device_entry();
DeviceEntry echo_device_entry();
// The line devices' (RS4SIM_LINE_DEVICES of the root CMakeLists.txt), in its order; the build
// generates it from the list (app/devices/line_device_entries.cpp.in).
std::vector<DeviceEntry> line_device_entries();

}  // namespace rs4sim::app
