#pragma once
// The narrated demos of the registered devices (app/demos/narration.h), run by `rs4sim demo`
// in its RunSession (app/runtime/run_session.h): SIGINT/SIGTERM end a demo between two waits
// with exit 130.
// Each returns 0 when every step happened as the manual or the spec says, 1 otherwise
// (the failing step is named on `out`).

#include "app/runtime/capture_option.h"
#include "app/runtime/grpc_cli.h"

#include <iosfwd>
#include <string>

namespace rs4sim::app {

class RunSession;

struct DemoOptions {
  CaptureOptions capture;
  std::string archive;         // the RS4 demo's parameter archive; empty: in memory only
  bool realtime = false;       // pace the simulated clock to the wall clock
  bool live_progress = false;  // redraw progress lines in place (stdout is a terminal)
  // --grpc …: the RS4 demo serves the read-only Observation API while it runs (real time).
  GrpcCliOptions grpc;
};

// RS4 scenario: one RS4/PROFIsafe, our GSD-configured class 1 master and a PROFIsafe
// F-host: boot, DP and PROFIsafe start-up, OSSD, protective-field violation, restart
// interlock, field-pair switching, a measurement telegram (0x92 + READ), an RS4 error as
// diagnosis alarm coming/going, a passivation with ACK_REI, and the parameter proxy with
// its archive: first commissioning, a set changed on site, a device exchange.
int run_rs4_demo(RunSession& session, std::ostream& out, const DemoOptions& options);

// Generic scenario: our master and two generic slaves with the 1.5 Mbit/s wire modelled:
// start-up, data exchange, a DPV1 write/read, an alarm round trip and a watchdog fault
// with recovery.
int run_generic_demo(RunSession& session, std::ostream& out, const DemoOptions& options);

// GridScan scenario: the curtain on the simulated line, the demo its door controller: the
// power-up messages, the communication test of [GridScan manual §10.3], a power cycle.
int run_gridscan_demo(RunSession& session, std::ostream& out, const DemoOptions& options);

// Polaris scenario: the barrier as Modbus RTU slave on the simulated line, the demo its
// master: an empty barrier, two objects in FL4 with the hole between them (PN2 after the
// filter's scans), a CRC error answered by exception 07, an unanswered broadcast.
int run_polaris_demo(RunSession& session, std::ostream& out, const DemoOptions& options);

// METRON scenario: the Receiver in slave line mode on the simulated line, the demo its host:
// the OSSD status after Equation 3's delay, an object's measurements, the error answers
// E1..E5, a parity error that costs the whole message its reply.
int run_metron_demo(RunSession& session, std::ostream& out, const DemoOptions& options);

}  // namespace rs4sim::app
