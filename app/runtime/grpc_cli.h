#pragma once
// The gRPC options every runtime command shares (`rs4sim run`; `master` and `demo` call the
// same helper), docs/rpc.md "Remote access":
//
//   --grpc HOST:PORT            serve the control API (port 0 = any free port)
//   --grpc-tls-cert FILE        PEM certificate chain  } TLS, both or neither
//   --grpc-tls-key FILE         PEM private key        }
//   --grpc-token-file FILE      bearer token: the file's first line, trimmed
//   RS4SIM_GRPC_TOKEN=TOKEN     bearer token from the environment (not with the file)
//
//   --http HOST:PORT            the live view and the same API as JSON over HTTP (docs/http.md)
//
// The token never comes from a command-line value (`ps` would show it). Loopback serves with
// neither; a non-loopback host (0.0.0.0 and :: included) needs TLS and a token. --http follows
// the same rule with the same files and token: HTTPS beyond loopback, the token on /api.


#include <cstddef>
#include <string>

namespace rs4sim::rpc {
struct ServerOptions;
}

namespace CLI {
class App;  // CLI11, included only where options are added (its header is costly to compile)
}

namespace rs4sim::app {

struct GrpcCliOptions {
  std::string address;     // --grpc HOST:PORT; empty = no API
  std::string tls_cert;    // --grpc-tls-cert FILE
  std::string tls_key;     // --grpc-tls-key FILE
  std::string token_file;  // --grpc-token-file FILE (the token of --http too)
  std::string http{};      // --http HOST:PORT; empty = no HTTP server ({}: see rpc::ServerOptions)
  std::size_t http_max_connections = 256;  // --http-max-connections N (0: no cap)

  // Neither --grpc nor --http: no API.
  [[nodiscard]] bool empty() const noexcept { return address.empty() && http.empty(); }
};

// The HTTP server's address of `options.http`: the host and the port (0 = any). Throws
// UsageError for what is not HOST:PORT and for a host beyond loopback without TLS and a bearer
// token in `protection` (the files and token grpc_server_options read; --grpc's rule).
struct HttpAddress {
  std::string host;
  unsigned port = 0;
};
HttpAddress http_address(const GrpcCliOptions& options, const rpc::ServerOptions& protection);
// The same without TLS or token (loopback only).
HttpAddress http_address(const GrpcCliOptions& options);

// The environment variable of the bearer token.
inline constexpr const char* kGrpcTokenEnv = "RS4SIM_GRPC_TOKEN";

// Adds --grpc, --grpc-tls-cert, --grpc-tls-key, --grpc-token-file, --http; `note` ends --grpc's help
// (what the API does in this command).
void add_grpc_options(CLI::App& cmd, GrpcCliOptions& options, const std::string& note = "");

// The server options of `options` (which must have --grpc or --http; address empty without
// --grpc, and --http checked, see http_address): the files read, the token from
// --grpc-token-file or `env_token` (RS4SIM_GRPC_TOKEN; nullptr = unset), and the rules
// checked. Throws UsageError with the reason: an unreadable or empty file, not PEM, both
// token sources, a non-loopback host without TLS or token (and which is missing).
rpc::ServerOptions grpc_server_options(const GrpcCliOptions& options, const char* env_token);
// The same with RS4SIM_GRPC_TOKEN from the process's environment.
rpc::ServerOptions grpc_server_options(const GrpcCliOptions& options);

// "TLS, bearer token" / "TLS" / "bearer token" / "" (plaintext, anyone on this machine).
std::string grpc_protection(const rpc::ServerOptions& options);

}  // namespace rs4sim::app
