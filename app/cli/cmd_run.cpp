// `rs4sim run`: one registered device (app/devices/device_registry.h) on a link, until Ctrl-C (or
// --duration), through the runtime's Asio shell (app/runtime/shell.h).
//
//   rs4sim run --address 4 --link pty                      (the RS4/PROFIsafe, the default)
//   rs4sim run --address 4 --address 5 --link pty          (two RS4s, two stations on one
//                                                           link: pty, serial, udp)
//   rs4sim run --device generic --address 5 --ident 0x1234 --cfg "10 20" --link pty
//   rs4sim run --device generic --address 5 --gsd X.gse --module "DI 8" --link pty
//   rs4sim run --bus bus.json --link pty                     (every station of the file)
//   rs4sim run ... --link serial --port /dev/ttyUSB0 --baud 1.5M
//   rs4sim run ... --link udp --listen 127.0.0.1:5001 --peer 127.0.0.1:5000
//   rs4sim run ... --link memory --duration 10     (our master on the in-memory bus,
//                                                   simulated time)
//   rs4sim run --device <byte device> --link pty --baud 19200 --blocked 9-13,25-34
//                                                  (the RS-485 devices: pty, serial, udp, and
//                                                   memory on the simulated clock; echo: no
//                                                   memory)
// With --link pty the first line on stdout is the pty's slave path for the DP master (or
// the byte device's client).
#include "app/cli/command.h"
#include "app/cli/link_cli.h"
#include "app/devices/bus_file.h"
#include "app/devices/device_options.h"
#include "app/runtime/grpc_cli.h"
#include "app/runtime/shell.h"
#include "dp/pdu/sap.h"

#include <charconv>
#include <iostream>
#include <memory>
#include <vector>

namespace rs4sim::app {
namespace {

struct RunOptions {
  std::string device;          // empty: rs4, or generic when --ident/--cfg describe a generic slave
  std::vector<int> addresses;  // --address, repeatable (rs4: one RS4 each)
  std::optional<std::string> blocked;
  DeviceOptions device_options;
  LinkOptions link;
  std::string bus;  // --bus FILE.json (app/devices/bus_file.h)
};

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : " | ") + n;
  return s;
}

// The devices' options: their help is the descriptions' (app/devices/device_options.h
// option_help; each entry refuses those it does not use).
void add_byte_device_options(CLI::App& cmd, RunOptions& o) {
  DeviceOptions& d = o.device_options;
  cmd.add_option("--elements", d.elements, option_help("--elements"));
  cmd.add_option("--beams", d.beams, option_help("--beams"));
  cmd.add_option("--model", d.model, option_help("--model"));
  cmd.add_option("--mode", d.mode, option_help("--mode"));
  cmd.add_option("--blocked", o.blocked, option_help("--blocked"));
  cmd.add_option("--door", d.door, option_help("--door"));
  cmd.add_option("--node", d.node, option_help("--node"));
  cmd.add_option("--wire-table", d.wire_table, option_help("--wire-table"));
  cmd.add_option("--mains", d.mains, option_help("--mains"))
      ->check(one_of("a mains state", {"on", "off"}));
  cmd.add_option("--format", d.format, option_help("--format"));
  cmd.add_option("--rs232", d.rs232, option_help("--rs232"));
  cmd.add_option("--pc-adapter", d.pc_adapter, option_help("--pc-adapter"))
      ->check(one_of("a PC adapter state", {"attached", "detached"}));
}

// A DP slave's address in operation, 0..125 [IEC 61158-4-3 addresses, SAPs]: 126 is the
// delivery address that only Set_Slave_Add moves a slave from (the RS4's GSD has
// Set_Slave_Add_supp = 0, so its switches' 126 never reaches data exchange), 127 the broadcast
// address [docs/decisions.md#rs4-address-126].
CLI::Validator slave_address() {
  return CLI::Validator(
      [](std::string& value) -> std::string {
        const int max = dp::pdu::sap::kMaxSlaveAddress;
        int a = -1;
        const char* end = value.data() + value.size();
        const auto [p, ec] = std::from_chars(value.data(), end, a);
        if (ec != std::errc{} || p != end) {
          return "'" + value + "' is not a number 0.." + std::to_string(max);
        }
        if (a >= 0 && a <= max) return {};
        return value + " is outside 0.." + std::to_string(max) +
               " (a DP slave in operation; 126 is the delivery address, which only "
               "Set_Slave_Add leaves, and the RS4 has none; 127 and 255 must not be used, "
               "[RS4 manual §4.5])";
      },
      "0.." + std::to_string(dp::pdu::sap::kMaxSlaveAddress));
}

Action setup(CLI::App& cmd) {
  auto o = std::make_shared<RunOptions>();
  DeviceOptions& d = o->device_options;
  LinkOptions& l = o->link;
  cmd.add_option("--device", o->device,
                 joined(device_names()) + " (default rs4; generic when --ident/--cfg are given)")
      ->check(one_of("a device", device_names()));
  cmd.add_option("--address", o->addresses,
                 "FDL address 0..125 (rs4: default 4; repeat it for several RS4s on one "
                 "real-time link)")
      ->check(slave_address());
  cmd.add_option("--ident", d.ident, option_help("--ident"));
  cmd.add_option("--cfg", d.cfg, option_help("--cfg"));
  cmd.add_option("--gsd", d.gsd, option_help("--gsd"));
  cmd.add_option("--module", d.modules, option_help("--module"));
  cmd.add_option("--f-dest-add", d.f_dest_add,
                 "with --gsd: the F_Dest_Add of the station's PROFIsafe F-modules (their address "
                 "switch; default: the GSD's F_Dest_Add)");
  cmd.add_option("--bus", o->bus,
                 "a whole bus from FILE.json: {\"stations\": [{\"address\": 4, \"device\": "
                 "\"rs4\"}, {\"address\": 5, \"gsd\": \"X.gse\", \"modules\": [...]}]}, all on "
                 "the one link");
  cmd.add_option("--boot-time", d.boot_time_ms, option_help("--boot-time"));
  cmd.add_option("--command-time", d.command_time_ms, option_help("--command-time"));
  cmd.add_option("--serial-number", d.serial_numbers, option_help("--serial-number"));
  cmd.add_option("--state", d.state_files, option_help("--state"));
  cmd.add_option("--adapter-response-time", d.response_time_ms,
                 option_help("--adapter-response-time"));
  add_byte_device_options(cmd, *o);
  add_link_options(cmd, l, LinkCommand::kRun);
  add_real_line_options(cmd, l);
  add_grpc_options(cmd, l.grpc,
                   "with --link memory the simulated clock moves only through the API");
  return [o]() -> int {
    DeviceOptions& dev = o->device_options;
    if (!o->addresses.empty()) {
      dev.address = o->addresses.front();
      dev.more_addresses.assign(o->addresses.begin() + 1, o->addresses.end());
    }
    if (o->blocked) dev.blocked = parse_blocked(*o->blocked);
    if (!o->bus.empty()) {
      if (!o->device.empty() || dev.address || !dev.gsd.empty() || !dev.ident.empty() ||
          !dev.cfg.empty() || !dev.modules.empty()) {
        throw UsageError("--bus " + o->bus +
                         " describes the stations: --device, --address, "
                         "--gsd, --module, --ident and --cfg go into the file");
      }
      return run_device(bus_device_entry(read_bus_file(o->bus, o->link.baud)), dev, o->link,
                        std::cout);
    }
    dev.link_baud = o->link.baud;
    if (!o->device.empty()) return run_device(*find_device(o->device), dev, o->link, std::cout);
    const bool generic = !dev.ident.empty() || !dev.cfg.empty() || !dev.gsd.empty();
    return run_device(
        find_device(generic ? stream::DeviceKind::kGeneric : stream::DeviceKind::kRs4), dev,
        o->link, std::cout);
  };
}

const CommandRegistration kRun("run", "run a virtual DP slave on a link (memory, pty, serial, udp)",
                               setup, Signals::kSession);

}  // namespace
}  // namespace rs4sim::app
