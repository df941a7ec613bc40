#pragma once
// The shell of the runtime: runs any registered device (app/devices/device_registry.h) on any
// link in a RunSession (app/runtime/run_session.h: the loop, signals, --duration, gRPC, the
// ordered stop), with the pty path printout and the end-of-run summary.
//
//   memory  our master + the device on the in-memory bus, simulated time (default
//           duration per device), summary + status; exit 0 when in data exchange
//   pty     a pseudo-terminal pair; the first stdout line is the slave side's path
//   serial  --port DEVICE at --baud
//   udp     one telegram per datagram, --listen HOST:PORT, --peer HOST:PORT
// A byte device (DeviceEntry::byte_device) runs on pty, serial and udp only, with a
// stream::ByteRunner, in its own LineSettings (its default rate, or --baud as bit/s).

#include "app/devices/device_registry.h"
#include "app/runtime/link_options.h"

#include <functional>
#include <iosfwd>
#include <string>

namespace rs4sim::app {

class RunSession;

// The file of --capture, opened for a run whose clock reads `clock_now` now (timestamps are
// then wall-clock time); nullptr without --capture. Throws std::runtime_error when it cannot
// be written.
std::unique_ptr<dp::link::Capture> open_link_capture(const LinkOptions& link,
                                                     dp::TimePoint clock_now);
// After the run: "rs4sim: capture: N telegrams in FILE" on stderr (stdout may carry --json
// lines), or the write error; returns false after a write error.
bool report_capture(const dp::link::Capture* capture, const LinkOptions& link);
// The same for a byte line's capture (line_capture.h): "rs4sim: capture: N frames in FILE".
class LineCapture;
bool report_line_capture(LineCapture* capture, const std::string& file);

// Validates both option sets, builds the device and runs it; returns the exit code
// (1 for a link error, reported on stderr).
int run_device(const DeviceEntry& device, DeviceOptions options, const LinkOptions& link,
               std::ostream& out);

// Runs a built instance (a device, or the master side of `rs4sim master`) on a real-time
// link (pty, serial, udp; `link` validated) in `session` until Ctrl-C/SIGTERM or --duration;
// returns the exit code (1 for a link error, reported on stderr).
int run_on_link(RunSession& session, DeviceInstance& instance, const LinkOptions& link,
                std::ostream& out);

// Runs a simulated segment (the device or our master with simulated RS4s on the in-memory
// bus, manual clock) for `simulated` seconds in slices, so that SIGINT/SIGTERM end it early
// (the summary is printed all the same); false when a signal ended it.
bool run_simulated(RunSession& session, double simulated,
                   const std::function<void(dp::Duration)>& run_for);

}  // namespace rs4sim::app
