// `rs4sim run`: one virtual slave on a link, until Ctrl-C (or --duration).
//
//   rs4sim run --device rs4 --address 4 --link pty        (the RS4/PROFIsafe, GSD RSIM5234)
//   rs4sim run --device generic --address 5 --ident 0x1234 --cfg "10 20" --link pty
//   rs4sim run ... --link serial --port /dev/ttyUSB0 --baud 1.5M
//   rs4sim run ... --link udp --listen 127.0.0.1:5001 --peer 127.0.0.1:5000
//   rs4sim run ... --link memory --duration 10     (our master on the in-memory bus,
//                                                   10 s of simulated time)
// With --link pty the first line on stdout is the pty's slave path for the DP master.
#include "app/command.h"
#include "app/rs4_run.h"
#include "app/run_options.h"
#include "dp/devices/generic_bus.h"
#include "dp/link/pty.h"
#include "dp/link/serial_transport.h"
#include "dp/link/station_runner.h"
#include "dp/link/udp_transport.h"

#include <boost/asio/signal_set.hpp>
#include <boost/asio/steady_timer.hpp>

#include <iostream>
#include <memory>

namespace rs4sim::app {
namespace {

namespace asio = boost::asio;
namespace link = dp::link;

struct RunOptions {
  std::string device = "generic";
  int address = -1;
  std::string ident;
  std::string cfg;
  std::string link = "memory";
  std::string port;
  std::string baud = "1.5M";
  std::string listen;
  std::string peer;
  double duration = 0;  // seconds; 0 = until Ctrl-C (memory link: 10 s simulated)
};

void trace_slave(dp::devices::GenericSlave& s) {
  s.slave().set_trace([a = s.address()](const dp::SlaveTransition& t) {
    std::cout << "slave " << int(a) << ": " << dp::state_name(t.from) << " -> " << dp::state_name(t.to)
              << " (" << dp::reason_name(t.why) << ")" << std::endl;
  });
}

void print_summary(const dp::devices::GenericSlave& s, const link::StationCounters& c) {
  std::cout << "slave " << int(s.address()) << ": state " << dp::state_name(s.slave().state())
            << ", data exchanges " << s.device().exchanges() << ", telegrams received " << c.received
            << ", sent " << c.sent << ", malformed " << c.malformed << ", link errors " << c.send_errors
            << std::endl;
}

int run_memory(const RunOptions& o, const dp::devices::GenericSlaveConfig& sc) {
  dp::devices::GenericBusConfig bc;
  bc.slaves = {sc};
  bc.master_address = sc.address == 1 ? 2 : 1;
  dp::devices::GenericBus bus(bc);
  trace_slave(bus.slave(sc.address));
  const double seconds = o.duration > 0 ? o.duration : 10.0;
  bus.run_for(std::chrono::duration_cast<dp::Duration>(std::chrono::duration<double>(seconds)));
  std::cout << "in-memory bus, " << seconds << " s simulated, master " << int(bc.master_address)
            << ": " << bus.master().counters().cycles << " cycles" << std::endl;
  print_summary(bus.slave(sc.address), bus.bus().counters(sc.address));
  return bus.slaves_in_data_exchange() == 1 ? 0 : 1;
}

std::unique_ptr<link::Transport> make_transport(const RunOptions& o, asio::io_context& io,
                                                std::unique_ptr<link::PseudoTerminal>& pty) {
  const auto baud = link::parse_baud_rate(o.baud);
  if (!baud) {
    throw UsageError("--baud " + o.baud + ": not a PROFIBUS rate; use one of " +
                     link::standard_baud_rate_list());
  }
  const link::LogFn note = [](const std::string& s) { std::cerr << "rs4sim: note: " << s << std::endl; };
  if (o.link == "pty") {
    pty = std::make_unique<link::PseudoTerminal>();
    std::cout << pty->slave_path() << std::endl;  // first line: where the DP master connects
    return std::make_unique<link::SerialTransport>(io, pty->release_master(), *baud, "pty", note);
  }
  if (o.link == "serial") {
    if (o.port.empty()) throw UsageError("--link serial needs --port DEVICE (e.g. /dev/ttyUSB0)");
    return std::make_unique<link::SerialTransport>(io, o.port, *baud, note);
  }
  if (o.listen.empty() || o.peer.empty()) {
    throw UsageError("--link udp needs --listen HOST:PORT and --peer HOST:PORT");
  }
  return std::make_unique<link::UdpTransport>(io, link::resolve_udp_endpoint(io, o.listen),
                                              link::resolve_udp_endpoint(io, o.peer));
}

int run_realtime(const RunOptions& o, const dp::devices::GenericSlaveConfig& sc) {
  asio::io_context io;
  std::unique_ptr<link::PseudoTerminal> pty;
  std::unique_ptr<link::Transport> transport;
  try {
    transport = make_transport(o, io, pty);
  } catch (const link::LinkException& e) {
    std::cerr << "rs4sim: " << e.what() << " [" << e.code().category().name() << ":"
              << e.code().value() << "]" << std::endl;
    return 1;
  }
  dp::RealClock clock;
  dp::devices::GenericSlave slave(sc);
  trace_slave(slave);
  link::StationRunner runner(io, clock, *transport);
  runner.add(slave);
  asio::signal_set signals(io, SIGINT, SIGTERM);
  asio::steady_timer limit(io);
  const auto stop = [&] {
    runner.stop();
    signals.cancel();
    limit.cancel();
  };
  signals.async_wait([&](const boost::system::error_code& ec, int) { if (!ec) stop(); });
  if (o.duration > 0) {
    limit.expires_after(std::chrono::duration_cast<dp::Duration>(std::chrono::duration<double>(o.duration)));
    limit.async_wait([&](const boost::system::error_code& ec) { if (!ec) stop(); });
  }
  std::cerr << "rs4sim: generic slave " << int(sc.address) << " (ident 0x" << std::hex << sc.ident_number
            << std::dec << ", cfg " << hex(sc.cfg) << ") on " << o.link << "; Ctrl-C to stop" << std::endl;
  runner.start();
  io.run();
  print_summary(slave, runner.counters());
  return 0;
}

Action setup(CLI::App& cmd) {
  auto o = std::make_shared<RunOptions>();
  auto boot_time_ms = std::make_shared<int>(30000);
  cmd.add_option("--device", o->device, "device to emulate: generic | rs4")
      ->check(CLI::IsMember({"generic", "rs4"}));
  cmd.add_option("--address", o->address, "FDL address 0..125 (rs4: 0..126, default 4)");
  cmd.add_option("--ident", o->ident, "generic: Ident_Number, e.g. 0x1234");
  cmd.add_option("--cfg", o->cfg, "generic: configuration identifiers in hex, e.g. \"10 20\"");
  cmd.add_option("--boot-time", *boot_time_ms, "rs4: boot time until operational in ms (default 30000)");
  cmd.add_option("--link", o->link, "memory | pty | serial | udp")
      ->check(CLI::IsMember({"memory", "pty", "serial", "udp"}));
  cmd.add_option("--port", o->port, "serial device (--link serial)");
  cmd.add_option("--baud", o->baud, "9.6k … 12M (serial/pty)");
  cmd.add_option("--listen", o->listen, "HOST:PORT to receive on (--link udp)");
  cmd.add_option("--peer", o->peer, "HOST:PORT of the master (--link udp)");
  cmd.add_option("--duration", o->duration, "seconds to run (0 = until Ctrl-C; memory: simulated)")
      ->check(CLI::NonNegativeNumber);
  return [o, boot_time_ms]() -> int {
    if (o->device == "rs4") {
      if (!o->ident.empty() || !o->cfg.empty()) {
        throw UsageError("--ident/--cfg are for --device generic; the RS4's come from its GSD");
      }
      const Rs4RunOptions r{o->address < 0 ? 4 : o->address, o->link, o->port, o->baud,
                            o->listen, o->peer, o->duration, *boot_time_ms};
      return run_rs4_device(r, std::cout);
    }
    if (o->address < 0 || o->ident.empty() || o->cfg.empty()) {
      throw UsageError("--device generic needs --address, --ident and --cfg");
    }
    const auto sc = generic_slave_config(o->address, o->ident, o->cfg);
    if (o->link == "memory") return run_memory(*o, sc);
    return run_realtime(*o, sc);
  };
}

const CommandRegistration kRun("run", "run a virtual DP slave on a link (memory, pty, serial, udp)", setup);

}  // namespace
}  // namespace rs4sim::app
