// `rs4sim demo`: the narrated scenario of a registered device (app/device_registry.h) on
// the simulated bus; the RS4's by default. Exits 0 when every step did what the manual or
// the spec says and 1 otherwise (CI runs it).
#include "app/command.h"
#include "app/device_registry.h"
#include "rpc/server.h"

#include <unistd.h>

#include <iostream>
#include <memory>

namespace rs4sim::app {
namespace {

const CommandRegistration kDemo(
    "demo", "narrated RS4/PROFIsafe scenario (or --device generic) on the simulated bus",
    [](CLI::App& cmd) {
      auto device = std::make_shared<std::string>("rs4");
      cmd.add_option("--device", *device, "rs4 (default) | generic")
          ->check(CLI::IsMember(device_names()));
      auto options = std::make_shared<DemoOptions>();
      add_capture_options(cmd, options->capture);
      cmd.add_option("--archive", options->archive,
                     "rs4: keep the sets the demo's proxy archives in this SQLite file");
      cmd.add_flag("--realtime", options->realtime,
                   "run at the device's real timing (the RS4 demo takes about a minute)");
      cmd.add_option("--grpc", options->grpc,
                     "rs4: serve the read-only Observation API on HOST:PORT while the demo "
                     "runs (loopback only; port 0 = any free port); implies --realtime");
      return [device, options]() {
        const DeviceEntry& entry = *find_device(*device);
        if (!entry.demo) throw UsageError("--device " + *device + " has no demo yet");
        if (!options->grpc.empty()) {
          if (*device != "rs4") throw UsageError("--grpc: only the RS4 demo serves the API");
          if (const auto why = rpc::check_listen_address(options->grpc); !why.empty()) {
            throw UsageError("--grpc: " + why);
          }
          options->realtime = true;  // on the simulated clock the demo is over at once
        }
        options->live_progress = isatty(STDOUT_FILENO) != 0;
        return entry.demo(std::cout, *options);
      };
    });

}  // namespace
}  // namespace rs4sim::app
