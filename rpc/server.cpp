#include "rpc/server.h"

#include <grpcpp/ext/proto_server_reflection_plugin.h>
#include <grpcpp/health_check_service_interface.h>
#include <grpcpp/security/server_credentials.h>
#include <grpcpp/server_builder.h>

#include <chrono>
#include <stdexcept>

namespace rs4sim::rpc {
namespace {

// Splits HOST:PORT ([::1]:PORT for IPv6); empty host on a malformed address.
std::pair<std::string, std::string> split(const std::string& address) {
  const auto colon = address.rfind(':');
  if (colon == std::string::npos || colon == 0) return {};
  std::string host = address.substr(0, colon);
  if (host.size() > 2 && host.front() == '[' && host.back() == ']') {
    host = host.substr(1, host.size() - 2);
  }
  return {host, address.substr(colon + 1)};
}

bool loopback(const std::string& host) {
  return host == "localhost" || host == "::1" || host.rfind("127.", 0) == 0;
}

}  // namespace

std::string check_listen_address(const std::string& address) {
  const auto [host, port] = split(address);
  if (host.empty() || port.empty() || port.find_first_not_of("0123456789") != std::string::npos ||
      port.size() > 5 || std::stoul(port) > 65535) {
    return "'" + address + "' is not HOST:PORT (e.g. 127.0.0.1:50051, port 0 = any free port)";
  }
  if (!loopback(host)) {
    return "'" + host +
           "' is not a loopback address: serving beyond this machine needs TLS and a bearer "
           "token, which this rs4sim does not have yet; use 127.0.0.1 (and an SSH tunnel)";
  }
  return {};
}

RpcServer::RpcServer(const ServerOptions& options, const std::vector<grpc::Service*>& services) {
  if (const auto why = check_listen_address(options.address); !why.empty()) {
    throw std::invalid_argument("--grpc: " + why);
  }
  grpc::EnableDefaultHealthCheckService(true);
  grpc::reflection::InitProtoReflectionServerBuilderPlugin();
  grpc::ServerBuilder builder;
  builder.AddListeningPort(options.address, grpc::InsecureServerCredentials(), &port_);
  for (auto* s : services) builder.RegisterService(s);
  server_ = builder.BuildAndStart();
  if (!server_ || port_ == 0) {
    throw std::runtime_error("--grpc: cannot listen on " + options.address);
  }
  address_ = split(options.address).first;
  if (address_.find(':') != std::string::npos) address_ = "[" + address_ + "]";
  address_ += ":" + std::to_string(port_);
}

RpcServer::~RpcServer() { shutdown(); }

void RpcServer::shutdown() {
  if (!server_) return;
  server_->Shutdown(std::chrono::system_clock::now() + std::chrono::seconds(2));
  server_->Wait();
  server_.reset();
}

}  // namespace rs4sim::rpc
