#pragma once
// The link options every runtime command shares (`rs4sim run`, `rs4sim master`), header-only:
// --link, --port, --baud, --listen, --peer, --duration and --capture into an app::LinkOptions.
// Each command shows only the options that mean something there: `master` drives no byte
// device and has no RS232 port.

#include "app/cli/command.h"
#include "app/runtime/cli_words.h"
#include "app/runtime/link_options.h"

#include <string>

namespace rs4sim::app {

enum class LinkCommand {
  kRun,     // a device: the RS4 (with its RS232 port), a DP slave, or a byte device
  kMaster,  // our master: PROFIBUS only
};

inline void add_link_options(CLI::App& cmd, LinkOptions& l, LinkCommand command) {
  const bool run = command == LinkCommand::kRun;
  const std::string peer = run ? "the master" : "the RS4's process";
  // In LinkKind's order: the transformer hands CLI11 the enum's number.
  cmd.add_option("--link", l.link, "memory | pty | serial | udp (default memory)")
      ->transform(one_of_index("a link", {"memory", "pty", "serial", "udp"}));
  cmd.add_option("--port", l.port, "serial device (--link serial), e.g. a pty path");
  cmd.add_option("--baud", l.baud,
                 run ? "PROFIBUS rate 9.6k … 12M (default 1.5M); a byte device: its bit rate, "
                       "e.g. 19200"
                     : "PROFIBUS rate 9.6k … 12M (default 1.5M)")
      ->each([&l](const std::string&) { l.baud_given = true; });
  cmd.add_option("--listen", l.listen, "HOST:PORT to receive on (--link udp)");
  cmd.add_option("--peer", l.peer, "HOST:PORT of " + peer + " (--link udp)");
  cmd.add_option("--duration", l.duration, "seconds to run (0 = until Ctrl-C; memory: simulated)")
      ->check(CLI::NonNegativeNumber);
  add_capture_options(cmd, l.capture, run);
  if (run) add_rs232_capture_option(cmd, l.capture);
}

// The real-line options of `rs4sim run` (docs/serial.md): --tsl, --rt-priority, --json.
inline void add_real_line_options(CLI::App& cmd, LinkOptions& l) {
  cmd.add_option("--tsl", l.tsl_us,
                 "the master's slot time in µs: a reply that would leave later is not sent "
                 "(it would collide with the retry) and is counted late");
  cmd.add_option("--rt-priority", l.rt_priority,
                 "run the loop thread under SCHED_FIFO at this priority (1..99) with locked "
                 "memory (needs CAP_SYS_NICE or ulimit -r); on a loaded machine it keeps a pty "
                 "slave from being starved (docs/serial.md)");
  cmd.add_flag("--json", l.json, "the end summary's turnaround as JSON lines");
}

}  // namespace rs4sim::app
