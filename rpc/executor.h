#pragma once
// Runs work on the thread that owns the cores and waits for it ([docs/design.md#one-event-loop]):
// gRPC threads never touch a core themselves, they hand a function to the loop.

#include <boost/asio/io_context.hpp>

#include <functional>

namespace rs4sim::rpc {

class Executor {
 public:
  virtual ~Executor() = default;
  // Runs `f` on the loop thread and returns once it ran; an exception of `f` is rethrown
  // here. Called on the loop thread itself, runs `f` at once.
  virtual void run(const std::function<void()>& f) = 0;

 protected:
  Executor() = default;
  Executor(const Executor&) = default;
  Executor& operator=(const Executor&) = default;
};

// The loop is an asio::io_context run by one thread (the shell's, or a test's).
class AsioExecutor final : public Executor {
 public:
  explicit AsioExecutor(boost::asio::io_context& io) : io_(io) {}
  void run(const std::function<void()>& f) override;

 private:
  boost::asio::io_context& io_;
};

}  // namespace rs4sim::rpc
