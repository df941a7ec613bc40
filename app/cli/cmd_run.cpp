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

// The byte devices' options (app/devices/device_options.h; each entry refuses those it does not use).
void add_byte_device_options(CLI::App& cmd, RunOptions& o) {
  DeviceOptions& d = o.device_options;
  cmd.add_option("--elements", d.elements, "byte devices: element count");
  cmd.add_option("--beams", d.beams, "byte devices: beam count");
  cmd.add_option("--model", d.model, "byte devices: model");
  cmd.add_option("--mode", d.mode, "byte devices: operating/reporting mode");
  cmd.add_option("--blocked", o.blocked,
                 "byte devices: interrupted elements/beams at start, 1-based, e.g. 9-13,25-34");
  cmd.add_option("--door", d.door, "byte devices: door position at start");
  cmd.add_option("--node", d.node, "byte devices: node number");
  cmd.add_option("--wire-table", d.wire_table,
                 "metron: the byte values and reply/report layouts from a JSON file (the "
                 "defaults: rs4sim metron-wire-table)");
  cmd.add_option("--mains", d.mains,
                 "gridscan: the mains at start: on (default: the power-up messages at once) | "
                 "off (SIGUSR1 or GridScan.SetPower powers it up, e.g. once the controller has "
                 "opened the pty)")
      ->check(one_of("a mains state", {"on", "off"}));
  cmd.add_option("--format", d.format,
                 "byte devices: character format override, e.g. 8E1 (--baud: the bit rate)");
  cmd.add_option("--rs232", d.rs232,
                 "rs4: serve the RS232 interface behind the PC adapter: pty | serial:DEVICE[@BAUD] "
                 "(SIGUSR1 attaches the PC adapter, SIGUSR2 removes it)");
  cmd.add_option("--pc-adapter", d.pc_adapter, "rs4: the PC adapter at start: attached | detached")
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
  cmd.add_option("--ident", d.ident, "generic: Ident_Number, e.g. 0x1234");
  cmd.add_option("--cfg", d.cfg, "generic: configuration identifiers in hex, e.g. \"10 20\"");
  cmd.add_option("--gsd", d.gsd,
                 "generic: the DP slave its GSD file describes (ident, Cfg, User_Prm_Data, "
                 "rates, MaxTsdr, DPV1, Max_Diag_Data_Len)");
  cmd.add_option("--module", d.modules,
                 "with --gsd: a module by its GSD name, repeat it in slot order (a compact "
                 "station's one module is implicit)");
  cmd.add_option("--f-dest-add", d.f_dest_add,
                 "with --gsd: the F_Dest_Add of the station's PROFIsafe F-modules (their address "
                 "switch; default: the GSD's F_Dest_Add)");
  cmd.add_option("--bus", o->bus,
                 "a whole bus from FILE.json: {\"stations\": [{\"address\": 4, \"device\": "
                 "\"rs4\"}, {\"address\": 5, \"gsd\": \"X.gse\", \"modules\": [...]}]}, all on "
                 "the one link");
  cmd.add_option("--boot-time", d.boot_time_ms,
                 "rs4: boot time until operational in ms (default 30000)");
  cmd.add_option("--command-time", d.command_time_ms,
                 "rs4: how long the RS4 processes a command in ms, 0..120000 (default 40; the "
                 "manual: up to 2 minutes)");
  cmd.add_option("--serial-number", d.serial_numbers,
                 "rs4: the unit's serial number 1..4294967295, one per --address in their order "
                 "(default 74565); the proxy downloads the archived set to a unit it has not "
                 "seen (device exchange)");
  cmd.add_option("--state", d.state_files,
                 "rs4: the unit's non-volatile memory (parameter set, passwords, serial number, "
                 "address switches) in FILE, one per --address: loaded at start, written on "
                 "every change, so a restart is the same unit with the same set");
  cmd.add_option("--adapter-response-time", d.response_time_ms,
                 "rs4: the PROFIsafe adapter's response time in ms, 0..1000 (default 10, as "
                 "the manual's technical data)");
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
        throw UsageError("--bus " + o->bus + " describes the stations: --device, --address, "
                         "--gsd, --module, --ident and --cfg go into the file");
      }
      return run_device(bus_device_entry(read_bus_file(o->bus, o->link.baud)), dev, o->link,
                        std::cout);
    }
    if (o->device.empty()) {
      o->device = dev.ident.empty() && dev.cfg.empty() && dev.gsd.empty() ? "rs4" : "generic";
    }
    dev.link_baud = o->link.baud;
    return run_device(*find_device(o->device), dev, o->link, std::cout);
  };
}

const CommandRegistration kRun("run", "run a virtual DP slave on a link (memory, pty, serial, udp)",
                               setup,
    Signals::kSession);

}  // namespace
}  // namespace rs4sim::app
