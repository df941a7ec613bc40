#include "app/runtime/grpc_cli.h"

#include "app/runtime/usage_error.h"
#include "app/runtime/whole_file.h"
#include "rpc/server.h"

#include <CLI/CLI.hpp>

#include <cstdlib>

namespace rs4sim::app {
namespace {

// The whole file; UsageError "OPTION FILE: cannot read: REASON" or "...: the file is empty".
std::string read_file(const std::string& option, const std::string& path) {
  auto file = read_whole_file(path);
  if (!file) throw UsageError(option + " " + path + ": cannot read: " + file.error);
  if (file.bytes.empty()) throw UsageError(option + " " + path + ": the file is empty");
  return std::move(file.bytes);
}

std::string trimmed(const std::string& text) {
  static constexpr const char* kSpace = " \t\r\n\v\f";
  const auto first = text.find_first_not_of(kSpace);
  if (first == std::string::npos) return {};
  return text.substr(first, text.find_last_not_of(kSpace) - first + 1);
}

std::string token_of(const GrpcCliOptions& o, const char* env_token) {
  if (!o.token_file.empty() && env_token != nullptr) {
    throw UsageError(std::string("--grpc-token-file and ") + kGrpcTokenEnv +
                     " both give a bearer token: use one");
  }
  std::string token;
  std::string source;
  if (!o.token_file.empty()) {
    source = "--grpc-token-file " + o.token_file;
    const std::string text = read_file("--grpc-token-file", o.token_file);
    token = trimmed(text.substr(0, text.find('\n')));
    if (token.empty()) throw UsageError(source + ": the first line (the token) is empty");
  } else if (env_token != nullptr) {
    source = kGrpcTokenEnv;
    token = trimmed(env_token);
    if (token.empty()) throw UsageError(source + " is set but empty: unset it or give a token");
  }
  if (const auto why = rpc::check_bearer_token(token); !why.empty()) {
    throw UsageError(source + ": " + why);
  }
  return token;
}

}  // namespace

void add_grpc_options(CLI::App& cmd, GrpcCliOptions& o, const std::string& note) {
  auto* grpc = cmd.add_option(
      "--grpc", o.address,
      "serve the control API on HOST:PORT (port 0 = any free port; a non-loopback host needs "
      "--grpc-tls-cert/--grpc-tls-key and a token)" +
          (note.empty() ? "" : "; " + note));
  auto* cert = cmd.add_option("--grpc-tls-cert", o.tls_cert,
                              "--grpc (and --http: HTTPS) over TLS: the server's PEM certificate "
                              "chain file");
  auto* key =
      cmd.add_option("--grpc-tls-key", o.tls_key,
                     "--grpc (and --http) over TLS: the PEM private key file");
  auto* token = cmd.add_option(
      "--grpc-token-file", o.token_file,
      std::string("--grpc: every call needs 'authorization: Bearer TOKEN', TOKEN being this "
                  "file's first line (or set ") +
          kGrpcTokenEnv + ")");
  auto* http = cmd.add_option(
      "--http", o.http,
      "serve the live view (a web page) and the same API as JSON over HTTP on HOST:PORT "
      "(port 0 = any free port; a non-loopback host needs --grpc-tls-cert/--grpc-tls-key, then "
      "HTTPS, and a token; docs/http.md)");
  auto* cap = cmd.add_option("--http-max-connections", o.http_max_connections,
                             "--http: connections open at once (default 256, 0 = no cap); "
                             "more wait in the listen queue until one closes (docs/http.md)");
  cap->needs(http);
  cert->needs(key);
  key->needs(cert);
  // TLS and the token guard both APIs: they need one of them (CLI11's needs() has no "or").
  cmd.parse_complete_callback([cert, token, grpc, http] {
    const bool api = grpc->count() > 0 || http->count() > 0;
    if (token->count() > 0 && !api) throw CLI::RequiresError("--grpc-token-file", "--grpc or --http");
    if (cert->count() > 0 && !api) throw CLI::RequiresError("--grpc-tls-cert", "--grpc or --http");
  });
}

HttpAddress http_address(const GrpcCliOptions& o) { return http_address(o, rpc::ServerOptions{}); }

HttpAddress http_address(const GrpcCliOptions& o, const rpc::ServerOptions& protection) {
  rpc::ServerOptions h = protection;  // the same TLS files and token as --grpc
  h.address = o.http;
  if (const auto why = rpc::check_server_options(h); !why.empty()) {
    const bool remote = why.find("is not a loopback address") != std::string::npos;
    throw UsageError("--http: " + why +
                     (remote ? std::string(" (TLS: --grpc-tls-cert FILE --grpc-tls-key FILE; "
                                           "token: --grpc-token-file FILE or ") +
                                   kGrpcTokenEnv + "; or an SSH tunnel: ssh -L PORT:127.0.0.1:PORT)"
                             : ""));
  }
  const auto colon = o.http.rfind(':');
  HttpAddress a{o.http.substr(0, colon), static_cast<unsigned>(std::stoul(o.http.substr(colon + 1)))};
  if (a.host.size() > 2 && a.host.front() == '[') a.host = a.host.substr(1, a.host.size() - 2);
  if (a.host == "localhost") a.host = "127.0.0.1";
  return a;
}

rpc::ServerOptions grpc_server_options(const GrpcCliOptions& o) {
  return grpc_server_options(o, std::getenv(kGrpcTokenEnv));
}

rpc::ServerOptions grpc_server_options(const GrpcCliOptions& o, const char* env_token) {
  rpc::ServerOptions s;
  s.address = o.address;
  if (o.tls_cert.empty() != o.tls_key.empty()) {
    throw UsageError(o.tls_cert.empty() ? "--grpc-tls-key needs --grpc-tls-cert FILE"
                                        : "--grpc-tls-cert needs --grpc-tls-key FILE");
  }
  if (!o.tls_cert.empty()) {
    s.tls_cert_chain = read_file("--grpc-tls-cert", o.tls_cert);
    if (const auto why = rpc::check_tls_cert_chain(s.tls_cert_chain); !why.empty()) {
      throw UsageError("--grpc-tls-cert " + o.tls_cert + ": " + why);
    }
    s.tls_private_key = read_file("--grpc-tls-key", o.tls_key);
    if (const auto why = rpc::check_tls_private_key(s.tls_private_key); !why.empty()) {
      throw UsageError("--grpc-tls-key " + o.tls_key + ": " + why);
    }
  }
  s.bearer_token = token_of(o, env_token);
  if (!o.http.empty()) (void)http_address(o, s);
  if (o.address.empty()) return s;  // --http alone: the in-process server, no port
  if (const auto why = rpc::check_server_options(s); !why.empty()) {
    const bool remote = why.find("is not a loopback address") != std::string::npos;
    throw UsageError("--grpc: " + why +
                     (remote
                          ? std::string(" (TLS: --grpc-tls-cert FILE --grpc-tls-key FILE; token: "
                                        "--grpc-token-file FILE or ") +
                                kGrpcTokenEnv + "; or serve on 127.0.0.1 behind an SSH tunnel)"
                          : ""));
  }
  return s;
}

std::string grpc_protection(const rpc::ServerOptions& s) {
  if (s.tls() && !s.bearer_token.empty()) return "TLS, bearer token";
  if (s.tls()) return "TLS";
  return s.bearer_token.empty() ? "" : "bearer token";
}

}  // namespace rs4sim::app
