// `rs4sim run --device rs4` (see app/rs4_run.h).
#include "app/rs4_run.h"

#include "app/command.h"
#include "app/run_options.h"
#include "dp/link/pty.h"
#include "dp/link/serial_transport.h"
#include "dp/link/station_runner.h"
#include "dp/link/udp_transport.h"
#include "rs4/device/rs4_segment.h"

#include <boost/asio/signal_set.hpp>
#include <boost/asio/steady_timer.hpp>

#include <iostream>
#include <memory>

namespace rs4sim::app {
namespace {

namespace asio = boost::asio;
namespace link = dp::link;
using rs4::device::Rs4Device;
using rs4::device::Rs4DeviceConfig;

Rs4DeviceConfig device_config(const Rs4RunOptions& o) {
  Rs4DeviceConfig c;
  c.switches = rs4::device::switches_for(static_cast<std::uint8_t>(o.address));
  c.boot_time = std::chrono::milliseconds(o.boot_time_ms);
  return c;
}

dp::Duration seconds(double s) {
  return std::chrono::duration_cast<dp::Duration>(std::chrono::duration<double>(s));
}

void print_state(std::ostream& out, const Rs4Device& d) {
  const auto v = d.adapter().view();
  out << "rs4 " << int(d.address()) << ": LED " << rs4::adapter::to_string(v.led) << ", RS4 "
      << rs4::scanner::to_string(v.rs4) << ", input byte " << hex(std::span(&v.input_byte, 1))
      << ", output byte " << hex(std::span(&v.output_byte, 1)) << ", PROFIsafe "
      << profisafe::to_string(v.fdevice) << std::endl;
}

int run_memory(const Rs4RunOptions& o, std::ostream& out) {
  rs4::device::Rs4SegmentConfig c;
  c.device = device_config(o);
  c.master.address = static_cast<std::uint8_t>(o.address);
  c.master_address = o.address == 1 ? 2 : 1;
  c.auto_ack_rei = true;
  rs4::device::Rs4Segment seg(c);
  seg.power_on();
  const double secs = o.duration > 0 ? o.duration : 40.0;
  seg.run_for(seconds(secs));
  out << "in-memory bus, " << secs << " s simulated, master " << int(c.master_address) << " (from "
      << "the GSD), F-host " << profisafe::to_string(seg.fhost().state()) << ", "
      << seg.master().counters().cycles << " cycles" << std::endl;
  print_state(out, seg.device());
  return seg.in_data_exchange() ? 0 : 1;
}

std::unique_ptr<link::Transport> make_transport(const Rs4RunOptions& o, asio::io_context& io,
                                                std::unique_ptr<link::PseudoTerminal>& pty,
                                                std::ostream& out) {
  const auto baud = link::parse_baud_rate(o.baud);
  const link::LogFn note = [](const std::string& s) { std::cerr << "rs4sim: note: " << s << std::endl; };
  if (o.link == "pty") {
    pty = std::make_unique<link::PseudoTerminal>();
    out << pty->slave_path() << std::endl;  // first line: where the DP master connects
    return std::make_unique<link::SerialTransport>(io, pty->release_master(), *baud, "pty", note);
  }
  if (o.link == "serial") return std::make_unique<link::SerialTransport>(io, o.port, *baud, note);
  return std::make_unique<link::UdpTransport>(io, link::resolve_udp_endpoint(io, o.listen),
                                              link::resolve_udp_endpoint(io, o.peer));
}

int run_realtime(const Rs4RunOptions& o, std::ostream& out) {
  asio::io_context io;
  std::unique_ptr<link::PseudoTerminal> pty;
  std::unique_ptr<link::Transport> transport;
  try {
    transport = make_transport(o, io, pty, out);
  } catch (const link::LinkException& e) {
    std::cerr << "rs4sim: " << e.what() << " [" << e.code().category().name() << ":" << e.code().value()
              << "]" << std::endl;
    return 1;
  }
  dp::RealClock clock;
  Rs4Device device(device_config(o));
  device.power_on(clock.now());
  link::StationRunner runner(io, clock, *transport);
  runner.add(device);
  asio::signal_set signals(io, SIGINT, SIGTERM);
  asio::steady_timer limit(io);
  const auto stop = [&] {
    runner.stop();
    signals.cancel();
    limit.cancel();
  };
  signals.async_wait([&](const boost::system::error_code& ec, int) { if (!ec) stop(); });
  if (o.duration > 0) {
    limit.expires_after(seconds(o.duration));
    limit.async_wait([&](const boost::system::error_code& ec) { if (!ec) stop(); });
  }
  std::cerr << "rs4sim: RS4/PROFIsafe at address " << o.address << " (ident 0x5234, F_Dest_Add "
            << 500 + o.address << ", boot " << o.boot_time_ms << " ms) on " << o.link
            << "; Ctrl-C to stop" << std::endl;
  runner.start();
  io.run();
  print_state(out, device);
  return 0;
}

}  // namespace

void check_rs4_run_options(const Rs4RunOptions& o) {
  if (o.address < 0 || o.address > 126) {
    throw UsageError("--address: " + std::to_string(o.address) +
                     " is outside 0..126 (the RS4's switches; 127 and 255 must not be used, §2)");
  }
  if (o.boot_time_ms < 0 || o.boot_time_ms > 600000) {
    throw UsageError("--boot-time: " + std::to_string(o.boot_time_ms) + " ms is outside 0..600000");
  }
  if (o.duration < 0) throw UsageError("--duration must not be negative");
  if (o.link != "memory" && o.link != "pty" && o.link != "serial" && o.link != "udp") {
    throw UsageError("--link " + o.link + ": use memory, pty, serial or udp");
  }
  if ((o.link == "pty" || o.link == "serial") && !link::parse_baud_rate(o.baud)) {
    throw UsageError("--baud " + o.baud + ": not a PROFIBUS rate; use one of " + link::standard_baud_rate_list());
  }
  if (o.link == "serial" && o.port.empty()) throw UsageError("--link serial needs --port DEVICE (e.g. /dev/ttyUSB0)");
  if (o.link == "udp" && (o.listen.empty() || o.peer.empty())) {
    throw UsageError("--link udp needs --listen HOST:PORT and --peer HOST:PORT");
  }
}

int run_rs4_device(const Rs4RunOptions& o, std::ostream& out) {
  check_rs4_run_options(o);
  if (o.link == "memory") return run_memory(o, out);
  return run_realtime(o, out);
}

}  // namespace rs4sim::app
