#pragma once
// `rs4sim run --device rs4`: one emulated RS4/PROFIsafe (rs4/device) on a link.
//
//   rs4sim run --device rs4 --address 4 --link pty            (prints the pty path first)
//   rs4sim run --device rs4 --address 4 --link serial --port /dev/ttyUSB0 --baud 1.5M
//   rs4sim run --device rs4 --address 4 --link udp --listen 127.0.0.1:5001 --peer 127.0.0.1:5000
//   rs4sim run --device rs4 --address 4 --link memory --duration 40 --boot-time 30000
//       (our master from the GSD + PROFIsafe F-host on the in-memory bus, simulated time)
//
// cmd_run.cpp (link author) calls run_rs4_device() for --device rs4; see
// docs/requests/rs4-device-to-lead.md.

#include <iosfwd>
#include <string>

namespace rs4sim::app {

struct Rs4RunOptions {
  int address = 4;                // station address 0..126 (set on the hex switches, §2)
  std::string link = "memory";    // memory | pty | serial | udp
  std::string port;               // --link serial
  std::string baud = "1.5M";      // serial / pty
  std::string listen, peer;       // --link udp
  double duration = 0;            // seconds; 0 = until Ctrl-C (memory: 40 s simulated)
  int boot_time_ms = 30000;       // RS4 boot until operational (§1: ≈30 s)
};

// Checks the options (UsageError with the reason for a bad value) and runs the device.
// Returns the exit code: 0 = ran (memory: reached data exchange), 1 = link or device error.
int run_rs4_device(const Rs4RunOptions& options, std::ostream& out);

// Validates without running (for the CLI layer and tests); throws UsageError.
void check_rs4_run_options(const Rs4RunOptions& options);

}  // namespace rs4sim::app
