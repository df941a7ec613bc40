#pragma once
// `--capture FILE` and `--capture-linktype` of the commands that drive a link (docs/capture.md):
// every telegram into a pcap file for Wireshark with the project's dissector.

#include "dp/link/capture.h"


#include <memory>
#include <string>

namespace CLI {
class App;  // CLI11, included only where options are added (its header is costly to compile)
}

namespace rs4sim::app {

struct CaptureOptions {
  std::string file;                // empty: no capture
  std::string linktype = "user0";  // user0 (147, the project's dissector) | 257 (PROFIBUS_DL)
  std::string rs232_file;          // --capture-rs232: the RS4's RS232 port (line_capture.h)
};

// `byte_devices`: the command may run a byte device, whose --capture records frames.
void add_capture_options(CLI::App& cmd, CaptureOptions& options, bool byte_devices = true);
// --capture-rs232 FILE (a real-time run of the RS4 with --rs232).
void add_rs232_capture_option(CLI::App& cmd, CaptureOptions& options);

// Opens the capture (nullptr without --capture). Simulated time is shifted to the wall clock
// at the call, so Wireshark shows today's date. Throws std::runtime_error when the file
// cannot be written.
std::unique_ptr<dp::link::Capture> open_capture(const CaptureOptions& options);
// The same for a run whose clock reads `clock_now` at this moment: timestamps are wall-clock
// time, whatever the clock's epoch.
std::unique_ptr<dp::link::Capture> open_capture(const CaptureOptions& options,
                                                dp::TimePoint clock_now);

// Attaches an open capture to a simulated bus (no-op for nullptr).
void attach_capture(dp::link::Capture* capture, dp::link::MemoryBus& bus);

}  // namespace rs4sim::app
