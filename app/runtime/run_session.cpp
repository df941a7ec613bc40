#include "app/runtime/run_session.h"

#include "app/runtime/grpc_serving.h"
#include "app/runtime/usage_error.h"
#include "http/http_server.h"
#include "rpc/server.h"

#include <boost/asio/post.hpp>

#include <pthread.h>

#include <csignal>
#include <iostream>
#include <ostream>

namespace rs4sim::app {

namespace {

void mask_stop_signals(int how) {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  pthread_sigmask(how, &set, nullptr);
}

}  // namespace

void block_stop_signals() { mask_stop_signals(SIG_BLOCK); }
void unblock_stop_signals() { mask_stop_signals(SIG_UNBLOCK); }

RunSession::RunSession(std::ostream& out)
    : out_(out),
      work_(boost::asio::make_work_guard(io_)),
      executor_(io_),
      signals_(io_, SIGINT, SIGTERM),
      limit_(io_) {
  signals_.async_wait([this](const boost::system::error_code& ec, int) {
    if (!ec) request_stop(StopReason::kSignal);
  });
  // The handlers are installed: a signal pending since main() blocked it is delivered now
  // and waits in the signal set for the loop.
  unblock_stop_signals();
}

RunSession::~RunSession() {
  // A session left without finish() (an exception on the way out) must not leave the server's
  // threads calling into a loop that no longer runs.
  if (grpc_ && !halted_) {
    // The steps may name objects of a caller's frame that has already gone.
    begin_steps_.clear();
    stop_steps_.clear();
    request_stop();
    try {
      io_.restart();
      io_.run();
    } catch (...) {  // nothing to report on the way out
    }
  }
}

void RunSession::serve_grpc(const GrpcCliOptions& options, ServiceList services) {
  const rpc::ServerOptions server = grpc_server_options(options);
  grpc_ = std::make_unique<GrpcServing>(server, std::move(services), out_,
                                        options.address.empty() ? "--http" : "--grpc");
  if (options.http.empty()) return;
  const HttpAddress address = http_address(options, server);
  http::HttpOptions h;
  h.host = address.host;
  h.port = static_cast<std::uint16_t>(address.port);
  h.bearer_token = server.bearer_token;
  h.tls_cert_chain = server.tls_cert_chain;
  h.tls_private_key = server.tls_private_key;
  h.max_connections = options.http_max_connections;
  http_ = std::make_unique<http::HttpServer>(io_, h, grpc_->in_process_channel());
  out_ << "http: listening on " << http_->url() << std::endl;
  rpc::ServerOptions http_protection;  // what guards the HTTP server (not --grpc's address)
  http_protection.tls_cert_chain = h.tls_cert_chain;
  http_protection.tls_private_key = h.tls_private_key;
  http_protection.bearer_token = h.bearer_token;
  if (const auto protection = grpc_protection(http_protection); !protection.empty()) {
    std::cerr << "rs4sim: http: " << protection
              << (h.bearer_token.empty() ? "" : " (every /api request; the page needs none)")
              << std::endl;
  }
}

void RunSession::on_stop(std::function<void()> step) { stop_steps_.push_back(std::move(step)); }

void RunSession::on_stop_begin(std::function<void()> step) {
  begin_steps_.push_back(std::move(step));
}

void RunSession::stop_after(double seconds) {
  if (seconds <= 0) return;
  limit_.expires_after(
      std::chrono::duration_cast<std::chrono::steady_clock::duration>(
          std::chrono::duration<double>(seconds)));
  limit_.async_wait([this](const boost::system::error_code& ec) {
    if (!ec) request_stop(StopReason::kDuration);
  });
}

void RunSession::request_stop(StopReason why) {
  if (stopping()) return;
  why_ = why;
  for (auto& step : begin_steps_) step();  // 0.
  if (http_) http_->close();                // 1.
  if (grpc_) {
    grpc_->stop_then(io_, [this] { halt(); });  // 1. the server, while the loop runs its calls
  } else {
    boost::asio::post(io_, [this] { halt(); });
  }
}

void RunSession::halt() {
  if (halted_) return;
  halted_ = true;
  for (auto& step : stop_steps_) step();  // 2.
  boost::system::error_code ignored;
  signals_.cancel(ignored);  // 3.
  limit_.cancel();
  work_.reset();
}

RunSession::StopReason RunSession::run() {
  io_.run();
  release_servers();
  return why_;
}

void RunSession::release_servers() {
  // The loop ran out, so the stop completed: the servers are down. Their services go now,
  // before the devices and segments they serve (which the caller destroys after the run).
  if (halted_) {
    // the forwarded calls the HTTP server cancelled complete on gRPC threads: gRPC goes
    // only after them (http_server.h wait_for_calls)
    if (http_ && !http_->wait_for_calls(std::chrono::seconds(5))) {
      out_ << "http: a forwarded call did not end within 5 s of the stop" << std::endl;
    }
    http_.reset();
    grpc_.reset();
  }
}

bool RunSession::run_until(std::chrono::steady_clock::time_point deadline) {
  io_.run_until(deadline);
  return !stopping();
}

bool RunSession::poll() {
  io_.poll();
  return !stopping();
}

void RunSession::finish() {
  request_stop();
  io_.restart();
  io_.run();
  release_servers();
}

}  // namespace rs4sim::app
