// `rs4sim run`: one registered device (app/device_registry.h) on a link, until Ctrl-C (or
// --duration), through the runtime's Asio shell (app/shell.h).
//
//   rs4sim run --address 4 --link pty                      (the RS4/PROFIsafe, the default)
//   rs4sim run --device generic --address 5 --ident 0x1234 --cfg "10 20" --link pty
//   rs4sim run ... --link serial --port /dev/ttyUSB0 --baud 1.5M
//   rs4sim run ... --link udp --listen 127.0.0.1:5001 --peer 127.0.0.1:5000
//   rs4sim run ... --link memory --duration 10     (our master on the in-memory bus,
//                                                   simulated time)
// With --link pty the first line on stdout is the pty's slave path for the DP master.
#include "app/command.h"
#include "app/link_cli.h"
#include "app/shell.h"

#include <iostream>
#include <memory>

namespace rs4sim::app {
namespace {

struct RunOptions {
  std::string device;  // empty: rs4, or generic when --ident/--cfg describe a generic slave
  int address = -1;
  DeviceOptions device_options;
  LinkOptions link;
};

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : " | ") + n;
  return s;
}

Action setup(CLI::App& cmd) {
  auto o = std::make_shared<RunOptions>();
  DeviceOptions& d = o->device_options;
  LinkOptions& l = o->link;
  cmd.add_option("--device", o->device,
                 joined(device_names()) + " (default rs4; generic when --ident/--cfg are given)")
      ->check(CLI::IsMember(device_names()));
  cmd.add_option("--address", o->address, "FDL address 0..125 (rs4: 0..126, default 4)");
  cmd.add_option("--ident", d.ident, "generic: Ident_Number, e.g. 0x1234");
  cmd.add_option("--cfg", d.cfg, "generic: configuration identifiers in hex, e.g. \"10 20\"");
  cmd.add_option("--boot-time", d.boot_time_ms,
                 "rs4: boot time until operational in ms (default 30000)");
  add_link_options(cmd, l, "the master");
  cmd.add_option("--grpc", l.grpc,
                 "serve the control API on HOST:PORT (loopback only; port 0 = any free port); "
                 "with --link memory the simulated clock moves only through the API");
  return [o]() -> int {
    DeviceOptions& dev = o->device_options;
    if (o->address >= 0) dev.address = o->address;
    if (o->device.empty()) o->device = dev.ident.empty() && dev.cfg.empty() ? "rs4" : "generic";
    return run_device(*find_device(o->device), dev, o->link, std::cout);
  };
}

const CommandRegistration kRun("run", "run a virtual DP slave on a link (memory, pty, serial, udp)",
                               setup);

}  // namespace
}  // namespace rs4sim::app
