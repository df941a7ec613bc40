#pragma once
// One run of `rs4sim run`, `rs4sim master` or `rs4sim demo` on its event loop
// ([docs/design.md#one-event-loop]): the io_context and its executor, the optional gRPC
// server, SIGINT/SIGTERM, --duration, and the ordered stop. Every command that runs a
// device, a master or a demo owns exactly one RunSession; servers such as gRPC (and the
// HTTP server of the live view) plug into it.
//
// The stop, whatever asked for it (a signal, --duration, request_stop()), goes in one order
// that cannot deadlock:
//   0. the first steps (on_stop_begin: e.g. end the event streams the clients hold);
//   1. the HTTP server closes its connections and cancels the calls it forwarded (on the
//      loop), then the gRPC server shuts down on a helper thread while the loop still runs
//      the calls it waits for (a gRPC call posts its work to this loop);
//   2. the stop steps run on the loop in the order they were added (the runners stop, the
//      device's services end their timers);
//   3. the signal set, the --duration timer and the work guard go, so the loop runs out.
//
// Signals: main() blocks SIGINT/SIGTERM before anything else (block_stop_signals()); the
// session installs its handlers in its constructor and then unblocks them, so a signal that
// arrived while the process was still starting is handled as soon as the loop runs, never
// by the default action.

#include "app/devices/device_registry.h"
#include "app/runtime/grpc_cli.h"
#include "dp/time/clock.h"
#include "rpc/executor.h"

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/signal_set.hpp>
#include <boost/asio/steady_timer.hpp>

#include <chrono>
#include <functional>
#include <iosfwd>
#include <memory>
#include <vector>

namespace rs4sim::http {
class HttpServer;
}

namespace rs4sim::app {

class GrpcServing;

// Blocks SIGINT and SIGTERM in the calling thread (and the threads it starts later) until a
// RunSession installs its handlers; unblock_stop_signals() undoes it for the commands that
// run none.
void block_stop_signals();
void unblock_stop_signals();

class RunSession {
 public:
  enum class StopReason { kNone, kSignal, kDuration, kRequested };

  explicit RunSession(std::ostream& out);
  RunSession(const RunSession&) = delete;
  RunSession& operator=(const RunSession&) = delete;
  ~RunSession();

  [[nodiscard]] boost::asio::io_context& io() noexcept { return io_; }
  [[nodiscard]] rpc::Executor& executor() noexcept { return executor_; }
  // What the loop's services read: the wall clock, for timers on the loop.
  [[nodiscard]] const dp::Clock& wall_clock() const noexcept { return wall_; }
  [[nodiscard]] ServiceContext service_context(const dp::Clock& clock) {
    return {executor_, io_, clock};
  }

  // Serves `services` over gRPC (--grpc, docs/rpc.md); prints "grpc: listening on ADDRESS".
  // With --http also over HTTP (docs/http.md), through the gRPC server's in-process channel
  // (without --grpc that server has no port); prints "http: listening on http://HOST:PORT/".
  // Throws UsageError for refused options, std::runtime_error when it cannot listen.
  void serve_grpc(const GrpcCliOptions& options, ServiceList services);
  [[nodiscard]] bool serving() const noexcept { return grpc_ != nullptr; }

  // A step of the ordered stop (2. above), run on the loop after the servers are down.
  void on_stop(std::function<void()> step);
  // A step run first (0. above), on the loop, before the servers shut down.
  void on_stop_begin(std::function<void()> step);
  // Stops after `seconds` of wall time (--duration on a real-time link); 0: never.
  void stop_after(double seconds);
  // Starts the ordered stop from the loop's thread (once; later calls do nothing).
  void request_stop(StopReason why = StopReason::kRequested);

  // Runs the loop until the stop has completed; the servers and their services are gone
  // when it returns.
  StopReason run();
  // Runs the loop until `deadline` at most (a paced simulation's wait); false once a stop
  // has been asked for.
  bool run_until(std::chrono::steady_clock::time_point deadline);
  // Runs what is ready without waiting; false once a stop has been asked for.
  bool poll();
  // Stops (if not yet) and runs the loop until the stop has completed (the servers are gone
  // then, as after run()).
  void finish();

  [[nodiscard]] bool stopping() const noexcept { return why_ != StopReason::kNone; }
  [[nodiscard]] StopReason stop_reason() const noexcept { return why_; }

 private:
  void halt();
  void release_servers();

  std::ostream& out_;
  boost::asio::io_context io_;
  boost::asio::executor_work_guard<boost::asio::io_context::executor_type> work_;
  rpc::AsioExecutor executor_;
  dp::RealClock wall_;
  boost::asio::signal_set signals_;
  boost::asio::steady_timer limit_;
  std::unique_ptr<GrpcServing> grpc_;
  std::unique_ptr<http::HttpServer> http_;  // on grpc_'s in-process channel
  std::vector<std::function<void()>> begin_steps_;
  std::vector<std::function<void()>> stop_steps_;
  StopReason why_ = StopReason::kNone;
  bool halted_ = false;
};

}  // namespace rs4sim::app
