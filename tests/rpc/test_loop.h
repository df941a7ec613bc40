#pragma once
// The loop a test's server and services run on, as in a run: an io_context kept running on its
// own thread, and the executor that hands it work. A fixture derives from it, calls
// start_loop() once its services exist and stop_loop() after its server has shut down.
#include "rpc/executor.h"
#include "rpc/server.h"

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>

#include <grpcpp/create_channel.h>
#include <grpcpp/security/credentials.h>

#include <memory>
#include <optional>
#include <thread>
#include <vector>

namespace rs4sim::rpc {

class TestLoop {
 protected:
  void start_loop() {
    loop_ = std::thread([this] { io_.run(); });
  }
  void stop_loop() {
    work_.reset();
    if (loop_.joinable()) loop_.join();
  }

  boost::asio::io_context io_;
  std::optional<boost::asio::executor_work_guard<boost::asio::io_context::executor_type>> work_{
      io_.get_executor()};
  AsioExecutor executor_{io_};
  std::thread loop_;
};

// A loop and a server of one service on loopback: serve() once the service exists,
// stop_serving() at the end.
class ServedLoop : protected TestLoop {
 protected:
  // Starts the loop, then the server of `service`; a client stub of `Api` on it.
  template <class Api>
  std::unique_ptr<typename Api::Stub> serve(grpc::Service& service) {
    start_loop();
    server_ = std::make_unique<RpcServer>(ServerOptions{}, std::vector<grpc::Service*>{&service});
    return Api::NewStub(
        grpc::CreateChannel(server_->address(), grpc::InsecureChannelCredentials()));
  }
  // Shuts the server down, then the loop.
  void stop_serving() {
    server_->shutdown();
    stop_loop();
  }

  std::unique_ptr<RpcServer> server_;
};

}  // namespace rs4sim::rpc
