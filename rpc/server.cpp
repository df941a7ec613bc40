#include "rpc/server.h"

#include <grpc/grpc_security_constants.h>
#include <grpcpp/ext/proto_server_reflection_plugin.h>
#include <grpcpp/health_check_service_interface.h>
#include <grpcpp/security/auth_metadata_processor.h>
#include <grpcpp/security/server_credentials.h>
#include <grpcpp/server_builder.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <stdexcept>
#include <string_view>

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

std::string check_syntax(const std::string& address) {
  const auto [host, port] = split(address);
  if (host.empty() || port.empty() || port.find_first_not_of("0123456789") != std::string::npos ||
      port.size() > 5 || std::stoul(port) > 65535) {
    return "'" + address + "' is not HOST:PORT (e.g. 127.0.0.1:50051, port 0 = any free port)";
  }
  return {};
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

std::string check_tls(const ServerOptions& o) {
  if (!o.tls()) return {};
  if (o.tls_cert_chain.empty()) return "TLS needs a certificate chain besides the private key";
  if (o.tls_private_key.empty()) return "TLS needs a private key besides the certificate chain";
  if (auto why = check_tls_cert_chain(o.tls_cert_chain); !why.empty()) return why;
  return check_tls_private_key(o.tls_private_key);
}

// Requires `authorization: Bearer <token>` on every call. Runs in the call's path (not
// blocking): a comparison, no I/O.
class BearerTokenProcessor final : public grpc::AuthMetadataProcessor {
 public:
  explicit BearerTokenProcessor(std::string token) : token_(std::move(token)) {}
  [[nodiscard]] bool IsBlocking() const override { return false; }
  grpc::Status Process(const InputMetadata& metadata, grpc::AuthContext* /*context*/,
                       OutputMetadata* consumed, OutputMetadata* /*response*/) override {
    const auto it = metadata.find("authorization");
    if (it == metadata.end()) {
      return {grpc::StatusCode::UNAUTHENTICATED,
              "missing authorization metadata (this server wants 'authorization: Bearer "
              "<token>')"};
    }
    const std::string value(it->second.data(), it->second.size());
    static constexpr std::string_view kScheme = "bearer ";
    const bool bearer =
        value.size() > kScheme.size() &&
        std::equal(kScheme.begin(), kScheme.end(), value.begin(),
                   [](char a, char b) { return a == std::tolower(static_cast<unsigned char>(b)); });
    if (!bearer) {
      return {grpc::StatusCode::UNAUTHENTICATED, "authorization metadata is not 'Bearer <token>'"};
    }
    if (!constant_time_equal(value.substr(kScheme.size()), token_)) {
      return {grpc::StatusCode::UNAUTHENTICATED, "wrong bearer token"};
    }
    consumed->emplace("authorization", value);  // the services never see the token
    return grpc::Status::OK;
  }

 private:
  const std::string token_;
};

std::shared_ptr<grpc::ServerCredentials> credentials(const ServerOptions& o) {
  std::shared_ptr<grpc::ServerCredentials> creds;
  if (o.tls()) {
    grpc::SslServerCredentialsOptions ssl;
    ssl.pem_key_cert_pairs.push_back({o.tls_private_key, o.tls_cert_chain});
    creds = grpc::SslServerCredentials(ssl);
  } else if (!o.bearer_token.empty()) {
    // Plaintext with a token (loopback only, checked before): local credentials put no bytes
    // on the wire (a plaintext client connects as to an insecure server), accept loopback
    // peers only, and, unlike insecure credentials, run an AuthMetadataProcessor.
    creds = grpc::experimental::LocalServerCredentials(LOCAL_TCP);
  } else {
    return grpc::InsecureServerCredentials();
  }
  if (!o.bearer_token.empty()) {
    creds->SetAuthMetadataProcessor(std::make_shared<BearerTokenProcessor>(o.bearer_token));
  }
  return creds;
}

}  // namespace

std::string check_tls_cert_chain(const std::string& pem) {
  if (!contains(pem, "-----BEGIN CERTIFICATE-----") ||
      !contains(pem, "-----END CERTIFICATE-----")) {
    return "the TLS certificate chain is not PEM (no '-----BEGIN CERTIFICATE-----' block)";
  }
  return {};
}

std::string check_tls_private_key(const std::string& pem) {
  if (!contains(pem, "-----BEGIN ") || !contains(pem, "PRIVATE KEY-----") ||
      !contains(pem, "-----END ")) {
    return "the TLS private key is not a PEM private key (no '-----BEGIN ... PRIVATE KEY-----' "
           "block)";
  }
  return {};
}

std::string check_bearer_token(const std::string& token) {
  for (std::size_t i = 0; i < token.size(); ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    if (c <= 0x20 || c >= 0x7F) {
      return "the bearer token has a character that is not printable ASCII (a space, control or "
             "non-ASCII character) at position " +
             std::to_string(i + 1);
    }
  }
  return {};
}

bool constant_time_equal(const std::string& given, const std::string& expected) {
  unsigned diff = given.size() == expected.size() ? 0U : 1U;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const auto g = i < given.size() ? static_cast<unsigned char>(given[i]) : 0U;
    diff |= g ^ static_cast<unsigned char>(expected[i]);
  }
  return diff == 0;
}

std::string check_listen_address(const std::string& address) {
  return check_server_options(ServerOptions{address});
}

std::string check_server_options(const ServerOptions& options) {
  if (auto why = check_syntax(options.address); !why.empty()) return why;
  if (auto why = check_tls(options); !why.empty()) return why;
  if (auto why = check_bearer_token(options.bearer_token); !why.empty()) return why;
  const std::string host = split(options.address).first;
  if (!loopback(host) && (!options.tls() || options.bearer_token.empty())) {
    const char* missing = !options.tls() && options.bearer_token.empty() ? "TLS and a bearer token"
                          : !options.tls()                               ? "TLS"
                                                                         : "a bearer token";
    return "'" + host +
           "' is not a loopback address: serving beyond this machine needs TLS and a bearer "
           "token; missing: " +
           missing;
  }
  return {};
}

RpcServer::RpcServer(const ServerOptions& options, const std::vector<grpc::Service*>& services) {
  const bool listens = !options.address.empty();
  if (const auto why = listens ? check_server_options(options) : check_bearer_token(options.bearer_token);
      !why.empty()) {
    throw std::invalid_argument("--grpc: " + why);
  }
  grpc::EnableDefaultHealthCheckService(true);
  grpc::reflection::InitProtoReflectionServerBuilderPlugin();
  grpc::ServerBuilder builder;
  if (listens) builder.AddListeningPort(options.address, credentials(options), &port_);
  for (auto* s : services) builder.RegisterService(s);
  run_.observe(services);
  builder.RegisterService(&run_);
  builder.SetOption(run_.builder_option());
  server_ = builder.BuildAndStart();
  if (!listens && server_) return;
  if (!server_ || port_ == 0) {
    throw std::runtime_error(
        "--grpc: cannot listen on " + options.address +
        (options.tls() ? " with TLS (the address is taken or not this machine's, or gRPC "
                         "refused the certificate or key: is the key the certificate's?)"
                       : ""));
  }
  address_ = split(options.address).first;
  if (address_.find(':') != std::string::npos) address_ = "[" + address_ + "]";
  address_ += ":" + std::to_string(port_);
}

RpcServer::~RpcServer() { shutdown(); }

std::shared_ptr<grpc::Channel> RpcServer::in_process_channel() {
  return server_->InProcessChannel(grpc::ChannelArguments());
}

void RpcServer::shutdown() {
  if (!server_) return;
  server_->Shutdown(std::chrono::system_clock::now() + std::chrono::seconds(2));
  server_->Wait();
  server_.reset();
}

}  // namespace rs4sim::rpc
