#include "app/shell.h"

#include "app/command.h"
#include "app/grpc_serving.h"
#include "dp/link/pty.h"
#include "dp/link/serial_transport.h"
#include "dp/link/station_runner.h"
#include "dp/link/udp_transport.h"
#include "rpc/executor.h"

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/signal_set.hpp>
#include <boost/asio/steady_timer.hpp>

#include <csignal>
#include <functional>
#include <iostream>

namespace rs4sim::app {
namespace {

namespace asio = boost::asio;
namespace link = dp::link;

dp::Duration seconds(double s) {
  return std::chrono::duration_cast<dp::Duration>(std::chrono::duration<double>(s));
}

int run_memory(const DeviceEntry& device, const DeviceOptions& o, const LinkOptions& l,
               std::ostream& out) {
  const auto segment = device.simulate(o);
  const double secs = l.duration > 0 ? l.duration : device.simulated_seconds;
  segment->run_for(seconds(secs));
  out << "in-memory bus, " << secs << " s simulated, master " << int(segment->master_address());
  segment->print_summary(out);
  return segment->healthy() ? 0 : 1;
}

// SIGINT/SIGTERM, and --duration seconds when positive, call `stop` on the loop.
void arm_stop(asio::signal_set& signals, asio::steady_timer& limit, double duration,
              const std::function<void()>& stop) {
  signals.async_wait([stop](const boost::system::error_code& ec, int) {
    if (!ec) stop();
  });
  if (duration > 0) {
    limit.expires_after(seconds(duration));
    limit.async_wait([stop](const boost::system::error_code& ec) {
      if (!ec) stop();
    });
  }
}

// --link memory --grpc: the segment stays on its manual clock and is driven by the API
// (SimTime) until Ctrl-C/SIGTERM or --duration wall seconds.
int run_memory_served(const DeviceEntry& device, const DeviceOptions& o, const LinkOptions& l,
                      std::ostream& out) {
  asio::io_context io;
  auto work = asio::make_work_guard(io);
  const auto segment = device.simulate(o);
  const dp::RealClock wall;
  rpc::AsioExecutor executor(io);
  GrpcServing serving(l.grpc, segment->services({executor, io, wall}), out);
  asio::signal_set signals(io, SIGINT, SIGTERM);
  asio::steady_timer limit(io);
  const auto stop = [&] {
    serving.stop_then(io, [&] {
      work.reset();
      signals.cancel();
      limit.cancel();
    });
  };
  arm_stop(signals, limit, l.duration, stop);
  std::cerr << "rs4sim: simulated bus on the manual clock, driven through the API; Ctrl-C to stop"
            << std::endl;
  io.run();
  out << "in-memory bus, served, master " << int(segment->master_address());
  segment->print_summary(out);
  return 0;
}

std::unique_ptr<link::Transport> make_transport(const LinkOptions& l, asio::io_context& io,
                                                std::unique_ptr<link::PseudoTerminal>& pty,
                                                std::ostream& out) {
  const auto baud = dp::parse_baud_rate(l.baud);
  const link::LogFn note = [](const std::string& s) {
    std::cerr << "rs4sim: note: " << s << std::endl;
  };
  if (l.link == "pty") {
    pty = std::make_unique<link::PseudoTerminal>();
    out << pty->slave_path() << std::endl;  // first line: where the DP master connects
    return std::make_unique<link::SerialTransport>(io, pty->release_master(), *baud, "pty", note);
  }
  if (l.link == "serial") return std::make_unique<link::SerialTransport>(io, l.port, *baud, note);
  return std::make_unique<link::UdpTransport>(io, link::resolve_udp_endpoint(io, l.listen),
                                              link::resolve_udp_endpoint(io, l.peer));
}

}  // namespace

int run_on_link(DeviceInstance& instance, const LinkOptions& l, std::ostream& out) {
  asio::io_context io;
  std::unique_ptr<link::PseudoTerminal> pty;
  std::unique_ptr<link::Transport> transport;
  try {
    transport = make_transport(l, io, pty, out);
  } catch (const link::LinkException& e) {
    std::cerr << "rs4sim: " << e.what() << " [" << e.code().category().name() << ":"
              << e.code().value() << "]" << std::endl;
    return 1;
  }
  dp::RealClock clock;
  instance.start(clock.now());
  link::StationRunner runner(io, clock, *transport);
  for (dp::Station* s : instance.stations()) runner.add(*s);
  rpc::AsioExecutor executor(io);
  std::unique_ptr<GrpcServing> serving;
  if (!l.grpc.empty()) {
    serving = std::make_unique<GrpcServing>(l.grpc, instance.services({executor, io, clock}), out);
  }
  asio::signal_set signals(io, SIGINT, SIGTERM);
  asio::steady_timer limit(io);
  const auto halt = [&] {
    runner.stop();
    signals.cancel();
    limit.cancel();
  };
  const auto stop = [&] {
    if (serving) {
      serving->stop_then(io, halt);
    } else {
      halt();
    }
  };
  arm_stop(signals, limit, l.duration, stop);
  std::cerr << "rs4sim: " << instance.describe() << " on " << l.link << "; Ctrl-C to stop"
            << std::endl;
  runner.start();
  io.run();
  instance.print_status(out, runner.counters());
  return 0;
}

void validate(const LinkOptions& l) {
  if (l.duration < 0) throw UsageError("--duration must not be negative");
  if (l.link != "memory" && l.link != "pty" && l.link != "serial" && l.link != "udp") {
    throw UsageError("--link " + l.link + ": use memory, pty, serial or udp");
  }
  if ((l.link == "pty" || l.link == "serial") && !dp::parse_baud_rate(l.baud)) {
    throw UsageError("--baud " + l.baud + ": not a PROFIBUS rate; use one of " +
                     dp::standard_baud_rate_list());
  }
  if (l.link == "serial" && l.port.empty()) {
    throw UsageError("--link serial needs --port DEVICE (e.g. /dev/ttyUSB0)");
  }
  if (l.link == "udp" && (l.listen.empty() || l.peer.empty())) {
    throw UsageError("--link udp needs --listen HOST:PORT and --peer HOST:PORT");
  }
  if (!l.grpc.empty()) {
    if (const auto why = rpc::check_listen_address(l.grpc); !why.empty()) {
      throw UsageError("--grpc: " + why);
    }
  }
}

int run_device(const DeviceEntry& device, DeviceOptions options, const LinkOptions& link,
               std::ostream& out) {
  device.validate(options);
  validate(link);
  if (link.link == "memory" && !link.grpc.empty()) {
    return run_memory_served(device, options, link, out);
  }
  if (link.link == "memory") return run_memory(device, options, link, out);
  const auto instance = device.build(options);
  return run_on_link(*instance, link, out);
}

}  // namespace rs4sim::app
