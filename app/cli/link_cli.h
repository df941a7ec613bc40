#pragma once
// The link options every runtime command shares (`rs4sim run`, `rs4sim master`), header-only:
// --link, --port, --baud, --listen, --peer, --duration into an app::LinkOptions.

#include "app/cli/command.h"
#include "app/runtime/link_options.h"

#include <map>

#include <string>

namespace rs4sim::app {

// `peer`: who is at the other end of a UDP link ("the master", "the RS4's process").
inline void add_link_options(CLI::App& cmd, LinkOptions& l, const std::string& peer) {
  const std::map<std::string, LinkKind> kinds{{"memory", LinkKind::kMemory},
                                              {"pty", LinkKind::kPty},
                                              {"serial", LinkKind::kSerial},
                                              {"udp", LinkKind::kUdp}};
  cmd.add_option("--link", l.link, "memory | pty | serial | udp")
      ->transform(CLI::CheckedTransformer(kinds));
  cmd.add_option("--port", l.port, "serial device (--link serial), e.g. a pty path");
  cmd.add_option("--baud", l.baud,
                 "9.6k … 12M (serial/pty; a byte device: its bit rate, e.g. 19200)")
      ->each([&l](const std::string&) { l.baud_given = true; });
  cmd.add_option("--listen", l.listen, "HOST:PORT to receive on (--link udp)");
  cmd.add_option("--peer", l.peer, "HOST:PORT of " + peer + " (--link udp)");
  cmd.add_option("--duration", l.duration, "seconds to run (0 = until Ctrl-C; memory: simulated)")
      ->check(CLI::NonNegativeNumber);
  add_capture_options(cmd, l.capture);
  add_rs232_capture_option(cmd, l.capture);
}

// The real-line options of `rs4sim run` (docs/serial.md): --tsl, --rt-priority, --json.
inline void add_real_line_options(CLI::App& cmd, LinkOptions& l) {
  cmd.add_option("--tsl", l.tsl_us,
                 "the master's slot time in µs: a reply that would leave later is not sent "
                 "(it would collide with the retry) and is counted late");
  cmd.add_option("--rt-priority", l.rt_priority,
                 "run the loop thread under SCHED_FIFO at this priority (1..99) with locked "
                 "memory (needs CAP_SYS_NICE or ulimit -r)");
  cmd.add_flag("--json", l.json, "the end summary's turnaround as JSON lines");
}

}  // namespace rs4sim::app
