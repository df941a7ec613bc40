#pragma once
// The device registry of the runtime: every device rs4sim emulates (`rs4`, `generic`, and
// later ones) registers one DeviceEntry (app/device_<name>.cpp, a static
// DeviceRegistration like the sub-commands). `rs4sim run` and `rs4sim demo` look devices
// up here and never name one: the Asio shell (app/shell.h) runs any entry on any link.
//
// An entry builds its station(s) from one validated DeviceOptions:
//   * for a real-time link (pty, serial, UDP): the device's own stations, talking to an
//     external master (DeviceInstance);
//   * for the in-memory link: the device with our class 1 master on a MemoryBus on the
//     manual clock (SimulatedSegment);
// and prints its status at the end of a run. Its narrated demo uses app/narration.h.

#include "app/demos.h"
#include "dp/link/counters.h"
#include "dp/station.h"

#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rs4sim::app {

// The device options of `rs4sim run`, by name; an entry's validate() checks the ones it
// uses, refuses the others and fills its defaults.
struct DeviceOptions {
  std::optional<int> address;  // station address (rs4: the hex switches, default 4)
  std::string ident;           // generic: Ident_Number, e.g. "0x1234"
  std::string cfg;             // generic: configuration identifiers in hex, e.g. "10 20"
  int boot_time_ms = 30000;    // rs4: boot until operational [RS4 manual §1]
};

// One device built for a real-time link.
class DeviceInstance {
 public:
  virtual ~DeviceInstance() = default;
  // The stations the link runs (they live as long as this object).
  [[nodiscard]] virtual std::vector<dp::Station*> stations() = 0;
  // Called once before the link starts (e.g. the RS4's power-on).
  virtual void start(dp::TimePoint now) { (void)now; }
  // "generic slave 5 (ident 0x1234, cfg 10 20)": the banner line names the device.
  [[nodiscard]] virtual std::string describe() const = 0;
  // The status line(s) at the end of a run; `link` = the link's counters.
  virtual void print_status(std::ostream& out, const dp::link::StationCounters& link) const = 0;
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
};

struct DeviceEntry {
  std::string name;
  double simulated_seconds = 10;  // --link memory without --duration
  // Checks the options (UsageError with the reason) and fills the defaults.
  std::function<void(DeviceOptions&)> validate;
  std::function<std::unique_ptr<DeviceInstance>(const DeviceOptions&)> build;
  std::function<std::unique_ptr<SimulatedSegment>(const DeviceOptions&)> simulate;
  // The narrated demo on the simulated bus; returns the exit code.
  std::function<int(std::ostream&, const DemoOptions&)> demo;
};

std::vector<DeviceEntry>& device_registry();
// nullptr for an unknown name.
const DeviceEntry* find_device(std::string_view name);
// "generic | rs4", for help texts.
std::vector<std::string> device_names();

struct DeviceRegistration {
  explicit DeviceRegistration(DeviceEntry entry) { device_registry().push_back(std::move(entry)); }
};

}  // namespace rs4sim::app
