#include "app/runtime/shell.h"

#include "app/devices/device_options.h"
#include "app/runtime/line_capture.h"
#include "app/runtime/real_line.h"
#include "app/runtime/run_session.h"
#include "app/runtime/usage_error.h"
#include "dp/link/profibus_line.h"
#include "dp/link/station_runner.h"
#include "rpc/executor.h"
#include "stream/byte_runner.h"
#include "stream/pty.h"
#include "stream/serial_transport.h"
#include "stream/udp_transport.h"

#include <boost/asio/signal_set.hpp>

#include <algorithm>
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

// --capture of an in-memory run: the bus's telegrams, or a byte device's line's frames.
bool open_memory_captures(SimulatedSegment& segment, const DeviceEntry& device,
                          const LinkOptions& l, std::unique_ptr<dp::link::Capture>& capture,
                          std::unique_ptr<LineCapture>& line_capture) {
  try {
    if (device.byte_device) {
      line_capture = open_line_capture("--capture", l.capture.file, segment.line_protocol(),
                                       dp::TimePoint{});
      if (line_capture && !segment.tap_line(line_capture->tap())) line_capture.reset();
    } else {
      capture = open_link_capture(l, dp::TimePoint{});
      if (segment.bus() != nullptr) attach_capture(capture.get(), *segment.bus());
    }
  } catch (const std::runtime_error& e) {
    std::cerr << "rs4sim: " << e.what() << std::endl;
    return false;
  }
  return true;
}

int run_memory(const DeviceEntry& device, const DeviceOptions& o, const LinkOptions& l,
               std::ostream& out) {
  RunSession session(out);
  const auto segment = device.simulate(o);
  std::unique_ptr<dp::link::Capture> capture;
  std::unique_ptr<LineCapture> line_capture;
  if (!open_memory_captures(*segment, device, l, capture, line_capture)) return 1;
  const double secs = l.duration > 0 ? l.duration : device.simulated_seconds;
  const bool whole = run_simulated(session, secs, [&](dp::Duration d) { segment->run_for(d); });
  out << (device.byte_device ? "in-memory line, " : "in-memory bus, ") << secs << " s simulated"
      << (whole ? "" : " (interrupted)");
  if (!device.byte_device) out << ", master " << int(segment->master_address());
  segment->print_summary(out);
  const bool written =
      report_capture(capture.get(), l) && report_line_capture(line_capture.get(), l.capture.file);
  return segment->healthy() && written ? 0 : 1;
}

// --link memory --grpc: the segment stays on its manual clock and is driven by the API
// (SimTime) until Ctrl-C/SIGTERM or --duration wall seconds.
int run_memory_served(const DeviceEntry& device, const DeviceOptions& o, const LinkOptions& l,
                      std::ostream& out) {
  const auto segment = device.simulate(o);  // outlives the session's server
  RunSession session(out);
  std::unique_ptr<dp::link::Capture> capture;
  std::unique_ptr<LineCapture> line_capture;
  if (!open_memory_captures(*segment, device, l, capture, line_capture)) return 1;
  session.serve_grpc(l.grpc, segment->services(session.service_context(session.wall_clock())));
  session.stop_after(l.duration);
  std::cerr << "rs4sim: simulated bus on the manual clock, driven through the API; Ctrl-C to stop"
            << std::endl;
  session.run();
  out << (device.byte_device ? "in-memory line, served" : "in-memory bus, served");
  if (!device.byte_device) out << ", master " << int(segment->master_address());
  segment->print_summary(out);
  const bool written =
      report_capture(capture.get(), l) && report_line_capture(line_capture.get(), l.capture.file);
  return written ? 0 : 1;
}

// The character format of the line: a byte device's own, else PROFIBUS 8E1 at --baud.
stream::LineSettings line_format(DeviceInstance& instance, const LinkOptions& l) {
  const auto bytes = instance.byte_devices();
  if (!bytes.empty()) return bytes.front()->line_settings();
  return link::profibus_line(*dp::parse_baud_rate(l.baud));
}

std::unique_ptr<stream::Transport> make_transport(const LinkOptions& l,
                                                  const stream::LineSettings& line,
                                                  asio::io_context& io,
                                                  std::unique_ptr<stream::PseudoTerminal>& pty,
                                                  std::ostream& out) {
  const stream::LogFn note = [](const std::string& s) {
    std::cerr << "rs4sim: note: " << s << std::endl;
  };
  if (l.link == LinkKind::kPty) {
    pty = std::make_unique<stream::PseudoTerminal>();
    auto transport =
        std::make_unique<stream::SerialTransport>(io, pty->release_master(), line, "pty", note);
    // First line: where the master/client connects; printed once the line is configured, so
    // a client that sets its own side's termios after reading it is not overridden.
    out << pty->slave_path() << std::endl;
    return transport;
  }
  if (l.link == LinkKind::kSerial) return std::make_unique<stream::SerialTransport>(io, l.port, line, note);
  return std::make_unique<stream::UdpTransport>(io, stream::resolve_udp_endpoint(io, l.listen),
                                                stream::resolve_udp_endpoint(io, l.peer));
}

// The runner of an instance: a ByteRunner for byte devices, else a StationRunner.
class LinkRunner {
 public:
  LinkRunner(asio::io_context& io, const dp::Clock& clock, stream::Transport& transport,
             DeviceInstance& instance, const LinkOptions& l)
      : instance_(instance), bytes_(instance.byte_devices()), link_(l) {
    if (bytes_.empty()) {
      link::RunnerOptions options;
      if (l.tsl_us) options.slot_time = std::chrono::microseconds(*l.tsl_us);
      stations_.emplace(io, clock, transport, options);
      for (dp::Station* s : instance.stations()) stations_->add(*s);
    } else {
      byte_runner_.emplace(io, clock, transport);
      for (stream::ByteDevice* d : bytes_) byte_runner_->add(*d);
    }
  }
  void start() { stations_ ? stations_->start() : byte_runner_->start(); }
  // Every frame of a byte device's line, with its direction.
  void tap(LineCapture* capture) {
    if (capture != nullptr && byte_runner_) byte_runner_->set_frame_tap(capture->tap());
  }
  [[nodiscard]] bool bytes() const { return !bytes_.empty(); }
  // Every PROFIBUS telegram on the line.
  void tap(dp::link::Capture* capture) {
    if (capture == nullptr || !stations_) return;
    stations_->set_frame_tap(
        [capture](std::span<const std::uint8_t> frame, dp::TimePoint at,
                  stream::FrameDirection dir) { capture->on_frame(frame, at, dir); });
  }
  void stop() { stations_ ? stations_->stop() : byte_runner_->stop(); }
  // The turnaround of a station (nullptr: a byte device's runner, or no such station).
  [[nodiscard]] const link::TurnaroundStats* turnaround(std::uint8_t address) const {
    return stations_ ? stations_->turnaround(address) : nullptr;
  }
  void print_status(std::ostream& out) const {
    if (stations_) {
      instance_.print_status(out, stations_->counters());
      for (const dp::Station* s : instance_.stations()) {
        const auto& t = *stations_->turnaround(s->address());
        // A station that answered nothing (our master's own station) has nothing to show.
        if (t.count() + t.late() > 0)
          print_turnaround(out, s->address(), t, link_.tsl_us, link_.json);
      }
    } else {
      instance_.print_byte_status(out, byte_runner_->counters());
    }
  }

 private:
  DeviceInstance& instance_;
  std::vector<stream::ByteDevice*> bytes_;
  const LinkOptions& link_;
  std::optional<link::StationRunner> stations_;
  std::optional<stream::ByteRunner> byte_runner_;
};

// The device's second port (the RS4's RS232 interface): its own transport (on a new
// pseudo-terminal when no path is given, the path printed) and runner.
struct SideLink {
  std::unique_ptr<stream::PseudoTerminal> pty;
  std::unique_ptr<stream::Transport> transport;
  std::optional<stream::ByteRunner> runner;
};

bool open_side_port(const SidePort& side, asio::io_context& io, SideLink& port, std::ostream& out) {
  try {
    const stream::LogFn note = [](const std::string& s) {
      std::cerr << "rs4sim: note: " << s << std::endl;
    };
    const auto line = side.device->line_settings();
    if (side.path.empty()) {
      port.pty = std::make_unique<stream::PseudoTerminal>();
      port.transport = std::make_unique<stream::SerialTransport>(io, port.pty->release_master(),
                                                                 line, side.name, note);
      out << side.name << ": " << port.pty->slave_path() << std::endl;
    } else {
      port.transport = std::make_unique<stream::SerialTransport>(io, side.path, line, note);
    }
  } catch (const stream::LinkException& e) {
    std::cerr << "rs4sim: " << side.name << ": " << e.what() << std::endl;
    return false;
  }
  return true;
}

// --capture of a real-time run (the link's telegrams, or a byte device's line's frames) and
// --capture-rs232 (the second port's frames).
struct LinkCaptures {
  std::unique_ptr<dp::link::Capture> link;
  std::unique_ptr<LineCapture> line;
  std::unique_ptr<LineCapture> side;

  bool open(DeviceInstance& instance, const LinkOptions& l, dp::TimePoint now) {
    try {
      if (!instance.byte_devices().empty()) {
        line = open_line_capture("--capture", l.capture.file, instance.line_protocol(), now);
      } else {
        link = open_link_capture(l, now);
      }
      side = open_line_capture("--capture-rs232", l.capture.rs232_file,
                               stream::LineProtocol::kRs4Rs232, now);
    } catch (const std::runtime_error& e) {
      std::cerr << "rs4sim: " << e.what() << std::endl;
      return false;
    }
    return true;
  }
  // Whether every capture was written to its end.
  [[nodiscard]] bool report(const LinkOptions& l) const {
    return report_capture(link.get(), l) && report_line_capture(line.get(), l.capture.file) &&
           report_line_capture(side.get(), l.capture.rs232_file);
  }
};

// SIGUSR1/SIGUSR2: the device's user actions (the RS4: PC adapter attached/removed), until the
// signal set is cancelled.
void await_user_signal(asio::signal_set& signals, DeviceInstance& instance,
                       const dp::Clock& clock) {
  signals.async_wait([&](const boost::system::error_code& ec, int signo) {
    if (ec) return;
    instance.on_user_signal(signo == SIGUSR2, clock.now());
    await_user_signal(signals, instance, clock);
  });
}

// --rt-priority: the loop thread, i.e. this one (the gRPC server's threads already run as they
// were). False when the system refused.
bool enter_loop_priority(const LinkOptions& l) {
  if (!l.rt_priority) return true;
  if (const std::string refused = enter_realtime(*l.rt_priority); !refused.empty()) {
    std::cerr << "rs4sim: " << refused << std::endl;
    return false;
  }
  std::cerr << "rs4sim: loop thread at SCHED_FIFO priority " << *l.rt_priority << ", memory locked"
            << std::endl;
  return true;
}

}  // namespace

int run_on_link(RunSession& session, DeviceInstance& instance, const LinkOptions& l,
                std::ostream& out) {
  asio::io_context& io = session.io();
  std::unique_ptr<stream::PseudoTerminal> pty;
  std::unique_ptr<stream::Transport> transport;
  try {
    transport = make_transport(l, line_format(instance, l), io, pty, out);
  } catch (const stream::LinkException& e) {
    std::cerr << "rs4sim: " << e.what() << " [" << e.code().category().name() << ":"
              << e.code().value() << "]" << std::endl;
    return 1;
  }
  const auto side = instance.side_port();
  SideLink side_port;
  if (side && !open_side_port(*side, io, side_port, out)) return 1;
  if (!side && !l.capture.rs232_file.empty()) {
    std::cerr << "rs4sim: --capture-rs232 needs the RS232 port (--rs232)" << std::endl;
    return 2;
  }
  dp::RealClock clock;
  LinkCaptures captures;
  if (!captures.open(instance, l, clock.now())) return 1;
  instance.start(clock.now());
  LinkRunner runner(io, clock, *transport, instance, l);
  runner.tap(captures.link.get());
  runner.tap(captures.line.get());
  if (side) {
    side_port.runner.emplace(io, clock, *side_port.transport);
    side_port.runner->add(*side->device);
    if (captures.side) side_port.runner->set_frame_tap(captures.side->tap());
  }
  asio::signal_set user_signals(io, SIGUSR1, SIGUSR2);
  await_user_signal(user_signals, instance, clock);
  if (!l.grpc.empty()) {
    ServiceContext context = session.service_context(clock);
    context.turnaround = [&runner](std::uint8_t address) { return runner.turnaround(address); };
    context.slot_time_us = l.tsl_us;
    session.serve_grpc(l.grpc, instance.services(context));
  }
  session.on_stop([&] {
    instance.stop_services();
    runner.stop();
    if (side_port.runner) side_port.runner->stop();
    user_signals.cancel();
  });
  if (!enter_loop_priority(l)) return 1;
  session.stop_after(l.duration);
  std::cerr << "rs4sim: " << instance.describe() << " on " << link_name(l.link)
            << "; Ctrl-C to stop" << std::endl;
  runner.start();
  if (side_port.runner) side_port.runner->start();
  session.run();
  runner.print_status(out);
  return captures.report(l) ? 0 : 1;
}

std::unique_ptr<dp::link::Capture> open_link_capture(const LinkOptions& link,
                                                     dp::TimePoint clock_now) {
  return open_capture(link.capture, clock_now);
}

bool report_capture(const dp::link::Capture* capture, const LinkOptions& link) {
  if (capture == nullptr) return true;
  if (capture->error()) {
    std::cerr << "rs4sim: --capture " << link.capture.file
              << ": writing stopped: " << capture->error().message() << std::endl;
    return false;
  }
  std::cerr << "rs4sim: capture: " << capture->records() << " telegrams in " << link.capture.file
            << std::endl;
  return true;
}

bool report_line_capture(LineCapture* capture, const std::string& file) {
  if (capture == nullptr) return true;
  if (const auto ec = capture->error() ? capture->error() : capture->flush()) {
    std::cerr << "rs4sim: capture " << file << ": writing stopped: " << ec.message() << std::endl;
    return false;
  }
  std::cerr << "rs4sim: capture: " << capture->records() << " frames in " << file << std::endl;
  return true;
}

bool run_simulated(RunSession& session, double simulated,
                   const std::function<void(dp::Duration)>& run_for) {
  // Slices of one simulated second: the loop sees a signal between two of them.
  constexpr double kSlice = 1.0;
  double done = 0;
  while (done < simulated) {
    if (!session.poll()) return false;
    const double step = std::min(kSlice, simulated - done);
    run_for(seconds(step));
    done += step;
  }
  return session.poll();
}

namespace {

// A byte device: --baud is its plain bit rate; the in-memory line only for the devices that
// have one (GridScan, METRON, Polaris: the harness is the client, through the API).
void prepare_byte_device(const DeviceEntry& device, DeviceOptions& options,
                         const LinkOptions& link) {
  if (link.link == LinkKind::kMemory && !device.simulate) {
    throw UsageError("--device " + device.name +
                     " has no in-memory link (no master or client of ours for it yet): run it "
                     "with --link pty and connect the client to the printed path (or use "
                     "--link serial/udp)");
  }
  if (link.baud_given) options.baud = parse_bit_rate(link.baud);
}

}  // namespace

int run_device(const DeviceEntry& device, DeviceOptions options, const LinkOptions& link,
               std::ostream& out) {
  if (device.byte_device) prepare_byte_device(device, options, link);
  device.validate(options);
  validate(link, device.byte_device);
  if (link.link == LinkKind::kMemory && !link.grpc.empty()) {
    return run_memory_served(device, options, link, out);
  }
  if (link.link == LinkKind::kMemory) return run_memory(device, options, link, out);
  // The device before the session, so that it outlives the session's servers on every path.
  const auto instance = device.build(options);
  RunSession session(out);
  return run_on_link(session, *instance, link, out);
}

}  // namespace rs4sim::app
