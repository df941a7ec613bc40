// app/runtime/grpc_cli.h: the gRPC options of the runtime commands into rpc::ServerOptions — the token
// file's first line trimmed, RS4SIM_GRPC_TOKEN, the TLS files, and each refusal's message.
#include "app/runtime/grpc_cli.h"

#include "app/cli/command.h"
#include "rpc/server.h"
#include "tests/scratch_dir.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace rs4sim::app {
namespace {

namespace fs = std::filesystem;

const std::string kData = RS4SIM_RPC_TEST_DATA;

class GrpcCliTest : public rs4sim::testing::ScratchDirTest {
 protected:
  GrpcCliTest() : ScratchDirTest("rs4sim_grpc_cli_") {}
  std::string file(const std::string& name, const std::string& text) {
    return write_file(name, text);
  }
  // The UsageError's message of grpc_server_options, or "" when it accepts.
  static std::string refusal(const GrpcCliOptions& o, const char* env = nullptr) {
    try {
      grpc_server_options(o, env);
    } catch (const UsageError& e) {
      return e.what();
    }
    return {};
  }
};

TEST_F(GrpcCliTest, TokenIsTheFilesFirstLineTrimmed) {
  GrpcCliOptions o{"127.0.0.1:0", "", "", file("token", "  \tabc-123\r\nsecond line\n")};
  const auto s = grpc_server_options(o, nullptr);
  EXPECT_EQ(s.bearer_token, "abc-123");
  EXPECT_FALSE(s.tls());
  EXPECT_EQ(grpc_protection(s), "bearer token");
}

TEST_F(GrpcCliTest, TokenFromTheEnvironment) {
  const auto s = grpc_server_options({"127.0.0.1:0", "", "", ""}, " from-env \n");
  EXPECT_EQ(s.bearer_token, "from-env");
  EXPECT_EQ(grpc_server_options({"127.0.0.1:0", "", "", ""}, nullptr).bearer_token, "");
}

TEST_F(GrpcCliTest, TlsFilesAreRead) {
  const auto s = grpc_server_options(
      {"0.0.0.0:0", kData + "/localhost.crt", kData + "/localhost.key", kData + "/token.txt"},
      nullptr);
  EXPECT_NE(s.tls_cert_chain.find("-----BEGIN CERTIFICATE-----"), std::string::npos);
  EXPECT_NE(s.tls_private_key.find("PRIVATE KEY-----"), std::string::npos);
  EXPECT_EQ(s.bearer_token, "rs4sim-test-token-0123456789");
  EXPECT_EQ(grpc_protection(s), "TLS, bearer token");
}

TEST_F(GrpcCliTest, BadTokenSourcesAreRefusedWithTheReason) {
  const std::string lo = "127.0.0.1:0";
  EXPECT_EQ(refusal({lo, "", "", file("empty", "")}),
            "--grpc-token-file " + (dir_ / "empty").string() + ": the file is empty");
  EXPECT_EQ(
      refusal({lo, "", "", file("blank", "  \nsecond\n")}),
      "--grpc-token-file " + (dir_ / "blank").string() + ": the first line (the token) is empty");
  EXPECT_NE(refusal({lo, "", "", (dir_ / "none").string()}).find("cannot read: No such file"),
            std::string::npos);
  EXPECT_EQ(refusal({lo, "", "", dir_.string()}),
            "--grpc-token-file " + dir_.string() + ": cannot read: Is a directory");
  EXPECT_EQ(refusal({lo, "", "", ""}, "  "),
            "RS4SIM_GRPC_TOKEN is set but empty: unset it or give a token");
  EXPECT_EQ(refusal({lo, "", "", file("t", "x\n")}, "y"),
            "--grpc-token-file and RS4SIM_GRPC_TOKEN both give a bearer token: use one");
  EXPECT_NE(refusal({lo, "", "", ""}, "two words")
                .find("RS4SIM_GRPC_TOKEN: the bearer token has "
                      "a character that is not printable ASCII"),
            std::string::npos);
}

TEST_F(GrpcCliTest, BadTlsFilesAreRefusedWithTheReason) {
  const std::string lo = "127.0.0.1:0";
  const std::string crt = kData + "/localhost.crt";
  const std::string key = kData + "/localhost.key";
  EXPECT_EQ(refusal({lo, crt, "", ""}), "--grpc-tls-cert needs --grpc-tls-key FILE");
  EXPECT_EQ(refusal({lo, "", key, ""}), "--grpc-tls-key needs --grpc-tls-cert FILE");
  EXPECT_EQ(refusal({lo, key, key, ""}),
            "--grpc-tls-cert " + key +
                ": the TLS certificate chain is not PEM (no '-----BEGIN CERTIFICATE-----' block)");
  EXPECT_NE(refusal({lo, crt, crt, ""})
                .find("--grpc-tls-key " + crt +
                      ": the TLS private key is "
                      "not a PEM private key"),
            std::string::npos);
  EXPECT_NE(refusal({lo, crt, (dir_ / "none").string(), ""}).find("cannot read"),
            std::string::npos);
}

TEST_F(GrpcCliTest, NonLoopbackSaysWhatIsMissingAndWhichOptionsGiveIt) {
  const std::string crt = kData + "/localhost.crt";
  const std::string key = kData + "/localhost.key";
  const std::string token = kData + "/token.txt";
  const auto none = refusal({"0.0.0.0:0", "", "", ""});
  EXPECT_NE(none.find("--grpc: '0.0.0.0' is not a loopback address"), std::string::npos) << none;
  EXPECT_NE(none.find("missing: TLS and a bearer token (TLS: --grpc-tls-cert FILE "
                      "--grpc-tls-key FILE; token: --grpc-token-file FILE or RS4SIM_GRPC_TOKEN"),
            std::string::npos)
      << none;
  EXPECT_NE(refusal({"[::]:0", crt, key, ""}).find("missing: a bearer token"), std::string::npos);
  EXPECT_NE(refusal({"10.1.2.3:50051", "", "", ""}, "tok").find("missing: TLS ("),
            std::string::npos);
  EXPECT_EQ(refusal({"0.0.0.0:0", crt, key, token}), "");
  EXPECT_EQ(refusal({"127.0.0.1", "", "", ""}),
            "--grpc: '127.0.0.1' is not HOST:PORT (e.g. 127.0.0.1:50051, port 0 = any free port)");
}

TEST(GrpcCliOptionsTest, TlsFilesComeInPairsAndNeedGrpc) {
  const auto parse = [](std::vector<std::string> args) {
    CLI::App app;
    GrpcCliOptions o;
    add_grpc_options(app, o, "a note");
    std::reverse(args.begin(), args.end());
    app.parse(args);
    return o;
  };
  const auto o = parse({"--grpc", "0.0.0.0:1", "--grpc-tls-cert", "c", "--grpc-tls-key", "k",
                        "--grpc-token-file", "t"});
  EXPECT_EQ(o.address, "0.0.0.0:1");
  EXPECT_EQ(o.tls_cert, "c");
  EXPECT_EQ(o.tls_key, "k");
  EXPECT_EQ(o.token_file, "t");
  EXPECT_THROW(parse({"--grpc", "x:1", "--grpc-tls-cert", "c"}), CLI::RequiresError);
  EXPECT_THROW(parse({"--grpc", "x:1", "--grpc-tls-key", "k"}), CLI::RequiresError);
  EXPECT_THROW(parse({"--grpc-token-file", "t"}), CLI::RequiresError);
  EXPECT_TRUE(parse({}).empty());
}

TEST(GrpcCliOptionsTest, HttpFollowsTheGrpcRuleAndSharesTheToken) {
  const auto parse = [](std::vector<std::string> args) {
    CLI::App app;
    GrpcCliOptions o;
    add_grpc_options(app, o);
    std::reverse(args.begin(), args.end());
    app.parse(args);
    return o;
  };
  auto o = parse({"--http", "127.0.0.1:0"});
  EXPECT_FALSE(o.empty());
  EXPECT_TRUE(o.address.empty());
  EXPECT_EQ(http_address(o).host, "127.0.0.1");
  EXPECT_EQ(http_address(o).port, 0U);
  o.http = "localhost:8080";
  EXPECT_EQ(http_address(o).host, "127.0.0.1");
  EXPECT_EQ(http_address(o).port, 8080U);
  o.http = "[::1]:80";
  EXPECT_EQ(http_address(o).host, "::1");
  // --http alone: the in-process gRPC server, no port; the token of --grpc
  o.http = "127.0.0.1:0";
  o.token_file = kData + "/token.txt";
  const auto s = grpc_server_options(o, nullptr);
  EXPECT_TRUE(s.address.empty());
  EXPECT_EQ(s.bearer_token, "rs4sim-test-token-0123456789");
  const auto refused = [&](const std::string& address) {
    GrpcCliOptions r;
    r.http = address;
    try {
      (void)http_address(r);
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(refused("0.0.0.0:8080"),
            "--http: '0.0.0.0' is not a loopback address: serving beyond this machine needs TLS "
            "and a bearer token; missing: TLS and a bearer token (TLS: --grpc-tls-cert FILE "
            "--grpc-tls-key FILE; token: --grpc-token-file FILE or RS4SIM_GRPC_TOKEN; or an SSH "
            "tunnel: ssh -L PORT:127.0.0.1:PORT)");
  // Beyond loopback with the --grpc files: HTTPS with the token; TLS alone is not enough.
  GrpcCliOptions remote;
  remote.http = "0.0.0.0:0";
  remote.tls_cert = kData + "/localhost.crt";
  remote.tls_key = kData + "/localhost.key";
  remote.token_file = kData + "/token.txt";
  const auto served = grpc_server_options(remote, nullptr);
  EXPECT_TRUE(served.tls());
  EXPECT_EQ(http_address(remote, served).host, "0.0.0.0");
  remote.token_file.clear();
  try {
    (void)grpc_server_options(remote, nullptr);
    ADD_FAILURE() << "--http 0.0.0.0 with TLS and no token accepted";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("missing: a bearer token"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(refused("127.0.0.1"),
            "--http: '127.0.0.1' is not HOST:PORT (e.g. 127.0.0.1:50051, port 0 = any free port)");
  EXPECT_EQ(refused("127.0.0.1:65536").substr(0, 36), "--http: '127.0.0.1:65536' is not HOS");
  // the token file needs one of the two APIs
  EXPECT_NO_THROW(parse({"--http", "127.0.0.1:0", "--grpc-token-file", "t"}));
  EXPECT_NO_THROW(parse({"--grpc-tls-cert", "c", "--grpc-tls-key", "k", "--http", "127.0.0.1:0"}));
  EXPECT_THROW(parse({"--grpc-tls-cert", "c", "--grpc-tls-key", "k"}),
               CLI::RequiresError);  // TLS needs one of the two APIs
}

}  // namespace
}  // namespace rs4sim::app
