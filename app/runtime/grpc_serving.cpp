#include "app/runtime/grpc_serving.h"

#include "app/runtime/usage_error.h"
#include "app/runtime/grpc_cli.h"

#include <boost/asio/post.hpp>

#include <iostream>
#include <ostream>
#include <stdexcept>

namespace rs4sim::app {

GrpcServing::GrpcServing(const rpc::ServerOptions& options, ServiceList services, std::ostream& out,
                         const std::string& option)
    : services_(std::move(services)) {
  if (services_.empty()) throw UsageError(option + ": this device has no API yet");
  std::vector<grpc::Service*> raw;
  for (const auto& s : services_) raw.push_back(s.get());
  try {
    server_ = std::make_unique<rpc::RpcServer>(options, raw);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  if (options.address.empty()) return;  // in-process only
  out << "grpc: listening on " << server_->address() << std::endl;
  if (const auto protection = grpc_protection(options); !protection.empty()) {
    std::cerr << "rs4sim: grpc: " << protection
              << (options.bearer_token.empty() ? "" : " (every call, health and reflection too)")
              << std::endl;
  }
}

GrpcServing::~GrpcServing() {
  if (stopper_.joinable()) stopper_.join();
}

void GrpcServing::stop_then(boost::asio::io_context& io, std::function<void()> then) {
  if (stopper_.joinable()) return;  // already stopping
  stopper_ = std::thread([this, &io, then = std::move(then)] {
    server_->shutdown();
    boost::asio::post(io, then);
  });
}

}  // namespace rs4sim::app
