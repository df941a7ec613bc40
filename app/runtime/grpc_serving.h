#pragma once
// The gRPC server of a run (`--grpc HOST:PORT`, docs/rpc.md) on the run's Asio loop: prints
// "grpc: listening on ADDRESS" (unchanged with TLS or a token: scripts parse it; a second
// line on stderr says how the API is protected) and stops in the order that cannot deadlock — the
// server shuts down on a helper thread while the loop still runs the calls it is waiting for, then
// the loop stops.

#include "app/devices/device_registry.h"
#include "rpc/server.h"

#include <boost/asio/io_context.hpp>

#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <thread>

namespace rs4sim::app {

class GrpcServing {
 public:
  // `options`: app/runtime/grpc_cli.h's grpc_server_options. Throws UsageError for refused options,
  // std::runtime_error when it cannot listen.
  // `option`: the option that asked for the API, for the messages ("--grpc", "--http"); an
  // empty options.address serves the in-process channel only (--http without --grpc).
  GrpcServing(const rpc::ServerOptions& options, ServiceList services, std::ostream& out,
              const std::string& option = "--grpc");
  GrpcServing(const GrpcServing&) = delete;
  GrpcServing& operator=(const GrpcServing&) = delete;
  ~GrpcServing();
  // Shuts the server down, then runs `then` on `io` (which must keep running meanwhile).
  void stop_then(boost::asio::io_context& io, std::function<void()> then);
  // The services inside this process (the HTTP server's route).
  [[nodiscard]] std::shared_ptr<grpc::Channel> in_process_channel() {
    return server_->in_process_channel();
  }

 private:
  ServiceList services_;
  std::unique_ptr<rpc::RpcServer> server_;
  std::thread stopper_;
};

}  // namespace rs4sim::app
