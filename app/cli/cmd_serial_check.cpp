// `rs4sim serial-check --port DEV [--baud B]`: the adapter, its latency, the measured
// turnaround and the slot time to enter for each rate (app/runtime/serial_check.h,
// docs/serial.md).
#include "app/cli/command.h"
#include "app/runtime/serial_check.h"
#include "app/runtime/usage_error.h"

#include <iostream>
#include <memory>

namespace rs4sim::app {
namespace {

Action setup(CLI::App& cmd) {
  auto o = std::make_shared<SerialCheckOptions>();
  cmd.add_option("--port", o->port, "the serial device, e.g. /dev/ttyUSB0 (or a pty path)")
      ->required();
  cmd.add_option("--baud", o->baud, "PROFIBUS rate to measure at, 9.6k … 12M (default 187.5k)");
  cmd.add_option("--address", o->address,
                 "the station at the other end to send FDL_Status to (default 4; a loopback "
                 "plug echoes the request instead)")
      ->check(CLI::Range(0, 126));
  cmd.add_option("--master", o->master, "our own FDL address (default 1)")
      ->check(CLI::Range(0, 126));
  cmd.add_option("--count", o->count, "requests to time (default 50)")
      ->check(CLI::Range(1, 100000));
  cmd.add_option("--timeout", o->timeout_ms, "ms to wait for each reply (default 200)")
      ->check(CLI::Range(1, 10000));
  cmd.add_option("--sysfs", o->sysfs, "sysfs root (default /sys)");
  return [o]() -> int {
    if (!dp::parse_baud_rate(o->baud)) {
      throw UsageError("--baud " + o->baud + ": not a PROFIBUS rate; use one of " +
                       dp::standard_baud_rate_list());
    }
    return serial_check(*o, std::cout, std::cerr);
  };
}

const CommandRegistration kSerialCheck(
    "serial-check",
    "check a serial port for a PROFIBUS line: adapter, latency, turnaround, slot time to enter",
    setup);

}  // namespace
}  // namespace rs4sim::app
