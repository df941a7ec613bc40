#pragma once
// The gRPC server of a run (docs/rpc.md): binds to the loopback address by default,
// with server reflection and the standard health service (grpc.health.v1) on, so generic
// clients (grpcurl, grpc_cli, Postman) can explore the API. Beyond loopback it serves only
// with TLS and a bearer token ("Remote access" in docs/rpc.md).

#include "rpc/run_service.h"

#include <grpcpp/channel.h>
#include <grpcpp/server.h>

#include <memory>
#include <string>
#include <vector>

namespace rs4sim::rpc {

struct ServerOptions {
  // HOST:PORT; port 0 picks a free one. A host other than loopback (127.0.0.0/8, ::1,
  // localhost), 0.0.0.0 and :: included, needs both TLS and a bearer token. Empty: no
  // listening port, only the in-process channel (the HTTP server's, `--http` without
  // `--grpc`).
  std::string address = "127.0.0.1:0";
  // TLS: the server's PEM certificate chain and its PEM private key (both or neither);
  // both empty = plaintext. (The {} keep ServerOptions{address} free of
  // -Wmissing-field-initializers.)
  std::string tls_cert_chain{};
  std::string tls_private_key{};
  // Not empty: every call (health and reflection included) must carry the metadata
  // `authorization: Bearer <token>`, else UNAUTHENTICATED. Printable ASCII, no spaces.
  std::string bearer_token{};

  [[nodiscard]] bool tls() const noexcept {
    return !tls_cert_chain.empty() || !tls_private_key.empty();
  }
};

// Empty when `address` is HOST:PORT with a loopback host; else the reason (the rule for a
// server without TLS and token; see check_server_options).
std::string check_listen_address(const std::string& address);

// Empty when the server can be built from `options`: HOST:PORT, the TLS pair complete and
// PEM, a token of allowed characters, and TLS plus a token for a non-loopback host; else the
// reason (what is missing).
std::string check_server_options(const ServerOptions& options);

// The parts of check_server_options, each empty or the reason: a PEM certificate chain, a
// PEM private key, a bearer token (printable ASCII, no spaces; empty = none).
std::string check_tls_cert_chain(const std::string& pem);
std::string check_tls_private_key(const std::string& pem);
std::string check_bearer_token(const std::string& token);

// `given == expected` in a time that does not depend on where they differ.
bool constant_time_equal(const std::string& given, const std::string& expected);

class RpcServer {
 public:
  // Throws std::invalid_argument for refused options (check_server_options), and
  // std::runtime_error when the bind fails or gRPC refuses the certificate or key. The
  // services must outlive the server. Serves rs4sim.v1.Run (rpc/run_service.h) besides.
  RpcServer(const ServerOptions& options, const std::vector<grpc::Service*>& services);
  RpcServer(const RpcServer&) = delete;
  RpcServer& operator=(const RpcServer&) = delete;
  ~RpcServer();

  // A channel to the services inside this process (the HTTP server's route to them):
  // no bytes on a socket, no bearer-token check (the HTTP server checks its own requests).
  [[nodiscard]] std::shared_ptr<grpc::Channel> in_process_channel();
  // "127.0.0.1:41234": the address clients use; empty without a listening port.
  [[nodiscard]] const std::string& address() const noexcept { return address_; }
  [[nodiscard]] int port() const noexcept { return port_; }
  // Stops accepting calls and waits for the running ones (bounded by a short deadline).
  void shutdown();

 private:
  RunService run_;  // declared before server_: outlives it
  std::unique_ptr<grpc::Server> server_;
  std::string address_;
  int port_ = 0;
};

}  // namespace rs4sim::rpc
