#pragma once
// The gRPC server of a run (docs/rpc.md): binds to the loopback address by default,
// with server reflection and the standard health service (grpc.health.v1) on, so generic
// clients (grpcurl, grpc_cli, Postman) can explore the API.

#include <grpcpp/server.h>

#include <memory>
#include <string>
#include <vector>

namespace rs4sim::rpc {

struct ServerOptions {
  // HOST:PORT; port 0 picks a free one. Only loopback hosts (127.0.0.0/8, ::1, localhost):
  // another address needs TLS and a bearer token, which are not built yet (docs/rpc.md).
  std::string address = "127.0.0.1:0";
};

// Empty when `address` is HOST:PORT with a loopback host; else the reason.
std::string check_listen_address(const std::string& address);

class RpcServer {
 public:
  // Throws std::invalid_argument for a refused address, std::runtime_error when the bind
  // fails. The services must outlive the server.
  RpcServer(const ServerOptions& options, const std::vector<grpc::Service*>& services);
  RpcServer(const RpcServer&) = delete;
  RpcServer& operator=(const RpcServer&) = delete;
  ~RpcServer();

  // "127.0.0.1:41234": the address clients use.
  [[nodiscard]] const std::string& address() const noexcept { return address_; }
  [[nodiscard]] int port() const noexcept { return port_; }
  // Stops accepting calls and waits for the running ones (bounded by a short deadline).
  void shutdown();

 private:
  std::unique_ptr<grpc::Server> server_;
  std::string address_;
  int port_ = 0;
};

}  // namespace rs4sim::rpc
