#pragma once
// The loop a test's server and services run on, as in a run: an io_context kept running on its
// own thread, and the executor that hands it work. A fixture derives from it, calls
// start_loop() once its services exist and stop_loop() after its server has shut down.
#include "rpc/executor.h"

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>

#include <optional>
#include <thread>

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

}  // namespace rs4sim::rpc
