// Remote access to the control API (docs/rpc.md "Remote access"): a real server on loopback
// with real TLS (the test certificate of tests/rpc/data, CN=localhost, SAN DNS:localhost and
// IP:127.0.0.1) and a bearer token on every call, health included; and the rules that refuse
// a non-loopback address without both.
#include "rs4_fixture.h"

#include <grpcpp/generic/generic_stub.h>

#include <fstream>
#include <sstream>

namespace rs4sim::rpc {
namespace {

std::string read_data(const std::string& name) {
  std::ifstream in(std::string(RS4SIM_RPC_TEST_DATA) + "/" + name, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  EXPECT_FALSE(s.str().empty()) << name;
  return s.str();
}

const std::string kToken = "s3cret-Token_0123456789";

ServerOptions tls_options(std::string address, std::string token) {
  return {std::move(address), read_data("localhost.crt"), read_data("localhost.key"),
          std::move(token)};
}

class RpcTlsTest : public RpcRs4Test {
 protected:
  void TearDown() override {
    if (secure_) secure_->shutdown();
    RpcRs4Test::TearDown();
  }
  void serve(const ServerOptions& options) {
    secure_ = std::make_unique<RpcServer>(
        options, std::vector<grpc::Service*>{&device_, &observation_, &time_, &faults_});
  }
  // TLS that trusts the test certificate; `token`: sent as call credentials when not empty.
  std::shared_ptr<grpc::ChannelCredentials> tls_credentials(const std::string& token = "") {
    grpc::SslCredentialsOptions ssl;
    ssl.pem_root_certs = read_data("localhost.crt");
    auto creds = grpc::SslCredentials(ssl);
    if (token.empty()) return creds;
    return grpc::CompositeChannelCredentials(creds, grpc::AccessTokenCredentials(token));
  }
  // SimTime.Now on the secure server over 127.0.0.1; `authorization`: extra metadata.
  grpc::Status now(const std::shared_ptr<grpc::ChannelCredentials>& creds,
                   const std::string& authorization = "") {
    const auto channel = grpc::CreateChannel("127.0.0.1:" + std::to_string(secure_->port()), creds);
    grpc::ClientContext ctx;
    ctx.set_deadline(std::chrono::system_clock::now() + 10s);
    if (!authorization.empty()) ctx.AddMetadata("authorization", authorization);
    v1::Empty req;
    v1::TimeResponse res;
    return v1::SimTime::NewStub(channel)->Now(&ctx, req, &res);
  }
  grpc::Status health(const std::shared_ptr<grpc::ChannelCredentials>& creds) {
    grpc::GenericStub stub(
        grpc::CreateChannel("127.0.0.1:" + std::to_string(secure_->port()), creds));
    grpc::ClientContext ctx;
    ctx.set_deadline(std::chrono::system_clock::now() + 10s);
    const grpc::Slice empty;
    grpc::ByteBuffer request(&empty, 1);
    grpc::ByteBuffer response;
    std::promise<grpc::Status> done;
    stub.UnaryCall(&ctx, "/grpc.health.v1.Health/Check", grpc::StubOptions(), &request, &response,
                   [&done](const grpc::Status& s) { done.set_value(s); });
    return done.get_future().get();
  }

  std::unique_ptr<RpcServer> secure_;
};

TEST_F(RpcTlsTest, TlsWithTheRightTokenAnswersEveryService) {
  serve(tls_options("127.0.0.1:0", kToken));
  const auto status = now(tls_credentials(kToken));
  EXPECT_TRUE(status.ok()) << status.error_message();
  const auto h = health(tls_credentials(kToken));
  EXPECT_TRUE(h.ok()) << h.error_message();
  // The header written by hand, scheme in another case (RFC 7235: case-insensitive).
  EXPECT_TRUE(now(tls_credentials(), "bearer " + kToken).ok());
}

TEST_F(RpcTlsTest, WrongTokenIsUnauthenticated) {
  serve(tls_options("127.0.0.1:0", kToken));
  for (const auto& wrong :
       {kToken + "x", kToken.substr(1), std::string("S3cret-Token_0123456789"), std::string("x")}) {
    const auto status = now(tls_credentials(wrong));
    EXPECT_EQ(status.error_code(), grpc::StatusCode::UNAUTHENTICATED) << wrong;
    EXPECT_EQ(status.error_message(), "wrong bearer token") << wrong;
  }
  const auto basic = now(tls_credentials(), "Basic " + kToken);
  EXPECT_EQ(basic.error_code(), grpc::StatusCode::UNAUTHENTICATED);
  EXPECT_EQ(basic.error_message(), "authorization metadata is not 'Bearer <token>'");
}

TEST_F(RpcTlsTest, NoTokenIsUnauthenticatedForEveryCallHealthIncluded) {
  serve(tls_options("127.0.0.1:0", kToken));
  const auto status = now(tls_credentials());
  EXPECT_EQ(status.error_code(), grpc::StatusCode::UNAUTHENTICATED);
  EXPECT_NE(status.error_message().find("missing authorization metadata"), std::string::npos)
      << status.error_message();
  EXPECT_EQ(health(tls_credentials()).error_code(), grpc::StatusCode::UNAUTHENTICATED);
}

TEST_F(RpcTlsTest, PlaintextClientToATlsServerFails) {
  serve(tls_options("127.0.0.1:0", kToken));
  const auto status = now(grpc::InsecureChannelCredentials(), "Bearer " + kToken);
  EXPECT_FALSE(status.ok());
  EXPECT_EQ(status.error_code(), grpc::StatusCode::UNAVAILABLE) << status.error_message();
}

TEST_F(RpcTlsTest, ClientThatDoesNotTrustTheCertificateFails) {
  serve(tls_options("127.0.0.1:0", kToken));
  grpc::SslCredentialsOptions ssl;
  ssl.pem_root_certs = read_data("untrusted.crt");
  const auto status = now(grpc::SslCredentials(ssl), "Bearer " + kToken);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::UNAVAILABLE) << status.error_message();
}

TEST_F(RpcTlsTest, LoopbackTlsWithoutTokenAnswersAnyone) {
  serve(tls_options("127.0.0.1:0", ""));
  const auto status = now(tls_credentials());
  EXPECT_TRUE(status.ok()) << status.error_message();
}

TEST_F(RpcTlsTest, LoopbackTokenWithoutTlsOverPlaintext) {
  serve(ServerOptions{"127.0.0.1:0", "", "", kToken});
  const auto plain = grpc::InsecureChannelCredentials();
  const auto right = now(plain, "Bearer " + kToken);
  EXPECT_TRUE(right.ok()) << right.error_message();
  EXPECT_EQ(now(plain, "Bearer nope").error_message(), "wrong bearer token");
  const auto missing = now(plain);
  EXPECT_EQ(missing.error_code(), grpc::StatusCode::UNAUTHENTICATED);
  EXPECT_NE(missing.error_message().find("missing authorization metadata"), std::string::npos);
}

TEST_F(RpcTlsTest, AllInterfacesWithTlsAndTokenServes) {
  serve(tls_options("0.0.0.0:0", kToken));
  EXPECT_EQ(secure_->address(), "0.0.0.0:" + std::to_string(secure_->port()));
  const auto status = now(tls_credentials(kToken));
  EXPECT_TRUE(status.ok()) << status.error_message();
  EXPECT_EQ(now(tls_credentials()).error_code(), grpc::StatusCode::UNAUTHENTICATED);
}

TEST_F(RpcTlsTest, CertificateGrpcRefusesIsAnErrorNotACrash) {
  // PEM blocks whose content is not a certificate, and a key that is not the certificate's.
  ServerOptions o = tls_options("127.0.0.1:0", kToken);
  o.tls_cert_chain = "-----BEGIN CERTIFICATE-----\nAAAA\n-----END CERTIFICATE-----\n";
  EXPECT_THROW(serve(o), std::runtime_error);
  o = tls_options("127.0.0.1:0", kToken);
  o.tls_private_key = read_data("untrusted.key");
  EXPECT_THROW(serve(o), std::runtime_error);
}

// ---- the rules, without a server ------------------------------------------------------------

TEST(ServerOptionsTest, NonLoopbackNeedsTlsAndToken) {
  const std::string cert = read_data("localhost.crt");
  const std::string key = read_data("localhost.key");
  const auto why = [](const ServerOptions& o) { return check_server_options(o); };
  for (const std::string address : {"0.0.0.0:0", "[::]:50051", "192.168.1.10:50051"}) {
    EXPECT_NE(why({address, "", "", ""}).find("missing: TLS and a bearer token"), std::string::npos)
        << address;
    EXPECT_NE(why({address, cert, key, ""}).find("missing: a bearer token"), std::string::npos);
    EXPECT_NE(why({address, "", "", "tok"}).find("missing: TLS"), std::string::npos);
    EXPECT_EQ(why({address, cert, key, "tok"}), "");
    EXPECT_NE(check_listen_address(address).find("is not a loopback address"), std::string::npos);
  }
  for (const std::string address : {"127.0.0.1:0", "[::1]:1", "localhost:50051"}) {
    EXPECT_EQ(check_listen_address(address), "") << address;
    EXPECT_EQ(why({address, cert, key, ""}), "") << address;
    EXPECT_EQ(why({address, "", "", "tok"}), "") << address;
  }
  EXPECT_THROW(RpcServer(ServerOptions{"0.0.0.0:0", "", "", ""}, {}), std::invalid_argument);
}

TEST(ServerOptionsTest, BadTlsOrTokenIsRefusedWithTheReason) {
  const std::string cert = read_data("localhost.crt");
  const std::string key = read_data("localhost.key");
  const auto why = [](const ServerOptions& o) { return check_server_options(o); };
  EXPECT_EQ(why({"127.0.0.1:0", cert, "", ""}),
            "TLS needs a private key besides the certificate chain");
  EXPECT_EQ(why({"127.0.0.1:0", "", key, ""}),
            "TLS needs a certificate chain besides the private key");
  EXPECT_NE(why({"127.0.0.1:0", key, key, ""}).find("certificate chain is not PEM"),
            std::string::npos);
  EXPECT_NE(why({"127.0.0.1:0", cert, cert, ""}).find("not a PEM private key"), std::string::npos);
  EXPECT_NE(why({"127.0.0.1:0", "", "", "two words"}).find("at position 4"), std::string::npos);
  EXPECT_NE(why({"127.0.0.1", cert, key, "t"}).find("is not HOST:PORT"), std::string::npos);
}

TEST(ServerOptionsTest, ConstantTimeEqual) {
  EXPECT_TRUE(constant_time_equal("abc", "abc"));
  EXPECT_TRUE(constant_time_equal("", ""));
  EXPECT_FALSE(constant_time_equal("abd", "abc"));
  EXPECT_FALSE(constant_time_equal("ab", "abc"));
  EXPECT_FALSE(constant_time_equal("abcd", "abc"));
  EXPECT_FALSE(constant_time_equal("", "abc"));
  EXPECT_FALSE(constant_time_equal("abc", ""));
}

}  // namespace
}  // namespace rs4sim::rpc
