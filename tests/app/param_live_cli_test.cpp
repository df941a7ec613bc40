// `rs4sim param --port` as a process against a live RS4 RS232 port on a pty (realtime): the
// test serves the pty's master side with an in-process RS4 (adapter + Rs232Port,
// tests/rs4/rs232/rs232_fixture.h) whose clock follows the wall clock, as `rs4sim run --rs232
// pty` will. get, set with the password, a wrong password changes nothing, diff against live.
#include "archive_cli_fixture.h"
#include "stream/pty.h"
#include "rs4/param_doc/parameter_document.h"
#include "tests/rs4/rs232/rs232_fixture.h"

#include <gtest/gtest.h>

#include <poll.h>
#include <unistd.h>

#include <atomic>
#include <thread>

namespace rs4sim::app::testing {
namespace {

using rs4::rs232::testing::PortFixture;

class ParamLive : public ArchiveCli {
 protected:
  void SetUp() override {
    ArchiveCli::SetUp();
    rs4.boot();
    rs4.port.attach(rs4.clock.now());
    expected_ = rs4.adapter.scanner().parameters();
    for (auto& pw : expected_.passwords) pw.fill(0xFF);  // never leave the device
    server_ = std::thread([this] { serve(); });
  }
  void TearDown() override {
    stop();
    ArchiveCli::TearDown();
  }
  void stop() {
    stopping_ = true;
    if (server_.joinable()) server_.join();
  }
  // The RS4 behind the pty: bytes in, deadlines on the wall clock, frames out.
  void serve() {
    const int fd = pty_.master_fd();
    auto last = std::chrono::steady_clock::now();
    std::array<std::uint8_t, 4096> buffer{};
    while (!stopping_) {
      pollfd p{fd, POLLIN, 0};
      const bool readable = ::poll(&p, 1, 5) > 0 && (p.revents & POLLIN) != 0;
      const auto now = std::chrono::steady_clock::now();
      rs4.clock.advance(std::chrono::duration_cast<stream::Duration>(now - last));
      last = now;
      if (readable) {
        const auto n = ::read(fd, buffer.data(), buffer.size());
        if (n > 0) rs4.port.on_bytes({buffer.data(), static_cast<std::size_t>(n)}, rs4.clock.now());
      }
      rs4.adapter.on_time(rs4.clock.now());
      rs4.port.on_time(rs4.clock.now());
      while (auto frame = rs4.port.take_transmit()) {
        std::size_t sent = 0;
        while (sent < frame->size()) {
          const auto n = ::write(fd, frame->data() + sent, frame->size() - sent);
          if (n <= 0) break;
          sent += static_cast<std::size_t>(n);
        }
      }
    }
  }
  CliResult param(const std::string& args) const {
    return run_rs4sim("param " + args + " --port " + pty_.slave_path());
  }

  stream::PseudoTerminal pty_;
  PortFixture rs4;
  rs4::scanner::ParameterSet expected_;
  std::atomic<bool> stopping_{false};
  std::thread server_;
};

TEST_F(ParamLive, GetReadsTheLiveSet) {
  const auto r = param("get");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, rs4::param_doc::to_document(expected_));
}

TEST_F(ParamLive, SetWritesWithThePasswordAndDiffAgainstLiveIsEmptyAfterwards) {
  write_text(dir_ / "doc.json", R"({"format": 1, "response_time_ms": 200, "start_pair": 3})");
  const auto doc = (dir_ / "doc.json").string();
  const auto r = param("set " + doc + " --password ROD4LE");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("response_time_ms: 80 -> 200"), std::string::npos) << r.out;
  const auto now = param("get");
  ASSERT_EQ(now.exit_code, 0) << now.err;
  write_text(dir_ / "now.json", now.out);
  const auto d = param("diff live " + (dir_ / "now.json").string());
  EXPECT_EQ(d.out, "no differences\n") << d.err;
  stop();
  EXPECT_EQ(rs4.adapter.scanner().parameters().response_steps, 3);
  EXPECT_EQ(rs4.adapter.scanner().parameters().start_pair, 3);
}

TEST_F(ParamLive, WrongPasswordChangesNothing) {
  write_text(dir_ / "doc.json", R"({"format": 1, "response_time_ms": 200})");
  const auto r = param("set " + (dir_ / "doc.json").string() + " --password guess");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("wrong password"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("nothing changed"), std::string::npos) << r.err;
  stop();
  EXPECT_EQ(rs4.adapter.scanner().parameters().response_steps, 0);
}

}  // namespace
}  // namespace rs4sim::app::testing
