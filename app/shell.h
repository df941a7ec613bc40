#pragma once
// The Asio shell of the runtime: runs any registered device (app/device_registry.h) on any
// link, the one place with a real-time loop, signals, --duration, the pty path printout
// and the end-of-run summary.
//
//   memory  our master + the device on the in-memory bus, simulated time (default
//           duration per device), summary + status; exit 0 when in data exchange
//   pty     a pseudo-terminal pair; the first stdout line is the slave side's path
//   serial  --port DEVICE at --baud
//   udp     one telegram per datagram, --listen HOST:PORT, --peer HOST:PORT
// A byte device (DeviceEntry::byte_device) runs on pty, serial and udp only, with a
// stream::ByteRunner, in its own LineSettings (its default rate, or --baud as bit/s).

#include "app/capture_option.h"
#include "app/device_registry.h"
#include "app/grpc_cli.h"

#include <iosfwd>
#include <string>

namespace rs4sim::app {

struct LinkOptions {
  std::string link = "memory";  // memory | pty | serial | udp
  std::string port;             // serial
  std::string baud = "1.5M";    // serial / pty (a byte device: plain bit/s, its default rate)
  bool baud_given = false;      // --baud was on the command line
  std::string listen, peer;     // udp
  double duration = 0;          // seconds; 0 = until Ctrl-C (memory: the device's default)
  // The gRPC API (--grpc HOST:PORT and its TLS/token options, app/grpc_cli.h, docs/rpc.md);
  // empty = none. With --link memory the run then stays on the manual clock and serves until
  // Ctrl-C (--duration: wall seconds): time moves only through the SimTime service.
  GrpcCliOptions grpc;
  // --capture FILE / --capture-linktype: every PROFIBUS telegram of the run into a pcap file
  // (docs/capture.md); not for byte devices.
  CaptureOptions capture;
};

// The file of --capture, opened for a run whose clock reads `clock_now` now (timestamps are
// then wall-clock time); nullptr without --capture. Throws std::runtime_error when it cannot
// be written.
std::unique_ptr<dp::link::Capture> open_link_capture(const LinkOptions& link,
                                                     dp::TimePoint clock_now);
// After the run: "rs4sim: capture: N telegrams in FILE" on stderr (stdout may carry --json
// lines), or the write error; returns false after a write error.
bool report_capture(const dp::link::Capture* capture, const LinkOptions& link);

// Throws UsageError with the reason for a bad combination. `byte_device`: --baud is the
// device's plain bit rate (checked by the device entry), not a PROFIBUS rate.
void validate(const LinkOptions& link, bool byte_device = false);

// Validates both option sets, builds the device and runs it; returns the exit code
// (1 for a link error, reported on stderr).
int run_device(const DeviceEntry& device, DeviceOptions options, const LinkOptions& link,
               std::ostream& out);

// Runs a built instance (a device, or the master side of `rs4sim master`) on a real-time
// link (pty, serial, udp; `link` validated) until Ctrl-C/SIGTERM or --duration; returns the
// exit code (1 for a link error, reported on stderr).
int run_on_link(DeviceInstance& instance, const LinkOptions& link, std::ostream& out);

}  // namespace rs4sim::app
