// `rs4sim demo`: the narrated scenario of a registered device (app/devices/device_registry.h) on
// the simulated bus; the RS4's by default. Exits 0 when every step did what the manual or
// the spec says and 1 otherwise (CI runs it).
#include "app/cli/command.h"
#include "app/devices/device_registry.h"
#include "app/runtime/archive_path.h"
#include "app/runtime/cli_words.h"
#include "app/runtime/grpc_cli.h"
#include "app/runtime/run_session.h"
#include "rpc/server.h"

#include <unistd.h>

#include <iostream>
#include <memory>
#include <string>

namespace rs4sim::app {
namespace {

// Why a demo other than the RS4's refuses --grpc/--http, naming the option(s) given. The RS4
// demo serves the read-only Observation service over its segment (rpc::SegmentTarget). The
// line demos (gridscan, metron, polaris) script their device on a stream::MemoryLine of their
// own, with no tap and no event hub, and what shows a line device (its GetState, docs/http.md
// "The page") lives in the device's service beside SetBlocked, InjectFault and Exchange, each
// of which would change the frames the demo compares with the bytes it expects.
// The generic demo's slaves have no service at all. `rs4sim run --device X --link memory`
// serves each of these devices on the simulated clock.
std::string api_refusal(const DeviceEntry& entry, const GrpcCliOptions& api) {
  const std::string& device = entry.name;
  const bool grpc = !api.address.empty();
  const bool http = !api.http.empty();
  const std::string given = grpc && http ? "--grpc and --http" : grpc ? "--grpc" : "--http";
  const std::string head = given + ": only the RS4 demo serves the API; the " + device + " demo ";
  if (entry.kind == stream::DeviceKind::kGeneric)
    return head + "does not (its generic slaves have no service of their own)";
  const std::string serve =
      std::string(grpc ? " --grpc HOST:PORT" : "") + (http ? " --http HOST:PORT" : "");
  return head +
         "does not (it compares each frame of its device with the bytes it expects, and the "
         "device's service would let a client change the device under it); rs4sim run --device " +
         device + " --link memory" + serve + " serves the device on the simulated clock";
}

const CommandRegistration kDemo(
    "demo", "narrated scenario of a device (RS4/PROFIsafe by default) on the simulated bus",
    [](CLI::App& cmd) {
      auto device = std::make_shared<std::string>("rs4");
      cmd.add_option("--device", *device, "rs4 (default) | generic | gridscan | metron | polaris")
          ->check(one_of("a device", device_names()));
      auto options = std::make_shared<DemoOptions>();
      add_capture_options(cmd, options->capture);
      cmd.add_option(
          "--archive", options->archive,
          "rs4: keep the sets the demo's proxy archives in this SQLite file or PostgreSQL "
          "URI (postgresql://user@host/db)");
      cmd.add_flag("--realtime", options->realtime,
                   "run at the device's real timing (the RS4 demo takes about a minute)");
      add_grpc_options(cmd, options->grpc,
                       "rs4: the read-only Observation service while the demo runs; implies "
                       "--realtime");
      return [device, options]() {
        const DeviceEntry& entry = *find_device(*device);
        if (!entry.demo) throw UsageError("--device " + *device + " has no demo yet");
        const bool rs4 = entry.kind == stream::DeviceKind::kRs4;
        if (!options->archive.empty() && !rs4) {
          throw UsageError("--archive: only the RS4 demo has a parameter proxy to archive");
        }
        const bool bus_demo = rs4 || entry.kind == stream::DeviceKind::kGeneric;
        if (!options->capture.file.empty() && !bus_demo) {
          throw UsageError("--capture: the " + *device +
                           " demo captures nothing; rs4sim run --device " + *device +
                           " --link memory --capture FILE captures its line");
        }
        checked_archive_path(options->archive);
        if (!options->grpc.empty()) {
          if (!rs4) throw UsageError(api_refusal(entry, options->grpc));
          (void)grpc_server_options(options->grpc);  // unreadable files, missing TLS/token
          options->realtime = true;  // on the simulated clock the demo is over at once
        }
        options->live_progress = isatty(STDOUT_FILENO) != 0;
        RunSession session(std::cout);
        return entry.demo(session, std::cout, *options);
      };
    },
    Signals::kSession);

}  // namespace
}  // namespace rs4sim::app
