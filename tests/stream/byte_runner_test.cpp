// ByteRunner over a real pseudo-terminal pair and over UDP on localhost, with the echo
// device (stream/echo_device.h). Wall clock: every wait is bounded and ends as soon as the
// condition holds; no fixed sleep decides a result.
#include "stream/byte_runner.h"

#include "stream/echo_device.h"
#include "stream/pty.h"
#include "stream/serial_transport.h"
#include "stream/udp_transport.h"
#include "tests/stream/run_until.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <functional>
#include <optional>

namespace rs4sim::stream {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;
namespace asio = boost::asio;

constexpr LineSettings k115200{115200, 8, Parity::kNone, 1};

using testing::run_until;

// The client side of the pty: raw writes, and reads of whatever has arrived.
class PtyClient {
 public:
  explicit PtyClient(const std::string& path) : fd_(::open(path.c_str(), O_RDWR | O_NOCTTY)) {}
  ~PtyClient() {
    if (fd_ >= 0) ::close(fd_);
  }
  PtyClient(const PtyClient&) = delete;
  PtyClient& operator=(const PtyClient&) = delete;
  [[nodiscard]] bool ok() const { return fd_ >= 0; }
  void write(const Bytes& b) const {
    ASSERT_EQ(::write(fd_, b.data(), b.size()), static_cast<ssize_t>(b.size()));
  }
  // Appends what is readable now to `got`.
  void read_into(Bytes& got) const {
    pollfd p{fd_, POLLIN, 0};
    while (::poll(&p, 1, 0) == 1 && (p.revents & POLLIN) != 0) {
      std::uint8_t buf[256];
      const ssize_t n = ::read(fd_, buf, sizeof buf);
      if (n <= 0) return;
      got.insert(got.end(), buf, buf + n);
    }
  }

 private:
  int fd_;
};

// Runs the loop until `client` has read at least `n` bytes; returns them.
Bytes read_at_least(asio::io_context& io, const PtyClient& client, std::size_t n) {
  Bytes got;
  (void)run_until(io, [&] {
    client.read_into(got);
    return got.size() >= n;
  });
  return got;
}

class BytePtyTest : public ::testing::Test {
 protected:
  asio::io_context io;
  RealClock clock;
  PseudoTerminal pty;
  EchoDevice echo{EchoOptions{k115200, 3.5, {}, 256}};

  // A runner on the pty's master side at `line` with `device` added, not started yet.
  ByteRunner& serve(ByteDevice& device, const LineSettings& line = k115200) {
    transport_.emplace(io, pty.release_master(), line, "pty");
    runner_.emplace(io, clock, *transport_);
    runner_->add(device);
    return *runner_;
  }
  std::optional<SerialTransport> transport_;
  std::optional<ByteRunner> runner_;
};

TEST_F(BytePtyTest, AFrameIsEchoedAfterTheIdleGap) {
  auto& runner = serve(echo);
  runner.start();
  PtyClient client(pty.slave_path());
  ASSERT_TRUE(client.ok());
  const Bytes frame = {0x02, 0x10, 0x20, 0x30, 0x03};
  client.write(frame);
  const Bytes got = read_at_least(io, client, frame.size());
  EXPECT_EQ(got, frame);
  EXPECT_EQ(runner.counters().bytes_received, frame.size());
  EXPECT_EQ(runner.counters().frames_sent, 1U);
  EXPECT_EQ(runner.counters().bytes_sent, frame.size());
  runner.stop();
}

// The device's idle gap, not the OS's read size, decides the frame: two writes within the
// gap (one read each) make one frame; after a longer pause, a second one.
TEST_F(BytePtyTest, APartialFrameAcrossReadsIsCompletedWithinTheGap) {
  EchoDevice slow{EchoOptions{k115200, 20000, {}, 256}};  // gap ≈ 1.7 s: reads stay one frame
  auto& runner = serve(slow);
  runner.start();
  PtyClient client(pty.slave_path());
  client.write({0x01, 0x02});
  ASSERT_TRUE(run_until(io, [&] { return runner.counters().bytes_received == 2; }));
  client.write({0x03});
  const Bytes got = read_at_least(io, client, 3);
  EXPECT_EQ(got, (Bytes{0x01, 0x02, 0x03}));
  EXPECT_GE(runner.counters().chunks_received, 2U);
  EXPECT_EQ(slow.framer_stats().frames, 1U);
  runner.stop();
}

TEST_F(BytePtyTest, DeadlinesFireOnTheRunnersTimer) {
  EchoDevice delayed{EchoOptions{k115200, 3.5, 30ms, 256}};
  auto& runner = serve(delayed);
  std::vector<std::pair<FrameDirection, TimePoint>> tapped;
  runner.set_frame_tap([&](std::span<const std::uint8_t>, TimePoint now, FrameDirection d) {
    tapped.emplace_back(d, now);
  });
  runner.start();
  PtyClient client(pty.slave_path());
  client.write({0x7E});
  const Bytes got = read_at_least(io, client, 1);
  ASSERT_EQ(tapped.size(), 2U);
  EXPECT_EQ(tapped[0].first, FrameDirection::kReceived);
  EXPECT_EQ(tapped[1].first, FrameDirection::kSent);
  EXPECT_GE(tapped[1].second - tapped[0].second, 30ms);  // the gap, then the 30 ms delay
  runner.stop();
}

TEST_F(BytePtyTest, AWakeFromOutsideSendsAtOnce) {
  auto& runner = serve(echo);
  runner.start();
  PtyClient client(pty.slave_path());
  echo.say({0xCA, 0xFE});  // as a scene change from the API would
  echo.say({0xBE});        // coalesced into the same posted drain
  const Bytes got = read_at_least(io, client, 3);
  EXPECT_EQ(got, (Bytes{0xCA, 0xFE, 0xBE}));
  EXPECT_EQ(runner.counters().frames_sent, 2U);
  runner.stop();
}

// A pty has no line: the device side's termios are the client's (Linux), so the transport
// must not switch it to PARMRK even with parity and a damaged handler installed; a byte FF
// from the client arrives as itself, not doubled.
TEST_F(BytePtyTest, APseudoTerminalWithParityStaysUnmarked) {
  constexpr LineSettings k19200e{19200, 8, Parity::kEven, 1};
  EchoDevice even{EchoOptions{k19200e, 3.5, {}, 256}};
  auto& runner = serve(even, k19200e);
  runner.start();
  PtyClient client(pty.slave_path());
  const int fd = ::open(pty.slave_path().c_str(), O_RDWR | O_NOCTTY);
  ASSERT_GE(fd, 0);
  termios tio{};
  ASSERT_EQ(tcgetattr(fd, &tio), 0);
  EXPECT_EQ(tio.c_iflag & PARMRK, 0U);
  client.write({0xFF, 0x00, 0x41});
  const Bytes got = read_at_least(io, client, 3);
  EXPECT_EQ(got, (Bytes{0xFF, 0x00, 0x41}));
  EXPECT_EQ(runner.counters().damaged_received, 0U);
  ::close(fd);
  runner.stop();
}

// mark_parity_errors() itself, on a tty that keeps its input flags (a pty slave): INPCK and
// PARMRK on, IGNPAR and ISTRIP off, read back.
TEST(SerialSettings, MarkParityErrorsSetsTheInputFlags) {
  PseudoTerminal pty;
  const int fd = ::open(pty.slave_path().c_str(), O_RDWR | O_NOCTTY);
  ASSERT_GE(fd, 0);
  termios tio{};
  ASSERT_EQ(tcgetattr(fd, &tio), 0);
  tio.c_iflag |= IGNPAR | ISTRIP;
  ASSERT_EQ(tcsetattr(fd, TCSANOW, &tio), 0);
  ASSERT_TRUE(mark_parity_errors(fd));
  ASSERT_EQ(tcgetattr(fd, &tio), 0);
  EXPECT_NE(tio.c_iflag & INPCK, 0U);
  EXPECT_NE(tio.c_iflag & PARMRK, 0U);
  EXPECT_EQ(tio.c_iflag & (IGNPAR | ISTRIP), 0U);
  ::close(fd);
  EXPECT_FALSE(mark_parity_errors(-1));  // not a terminal
}

// A transport that reports damaged characters (what SerialTransport does on an adapter with
// PARMRK): the runner hands each to every device, in line order with the good bytes, and
// counts it.
class ScriptedTransport final : public Transport {
 public:
  [[nodiscard]] bool datagram() const override { return false; }
  void start(BytesFn on_bytes, ErrorFn /*on_error*/) override { on_bytes_ = std::move(on_bytes); }
  void set_damaged_handler(DamagedFn on_damaged) override { on_damaged_ = std::move(on_damaged); }
  void send(std::span<const std::uint8_t> frame) override {
    sent.emplace_back(frame.begin(), frame.end());
  }
  void close() override {}
  BytesFn on_bytes_;
  DamagedFn on_damaged_;
  std::vector<Bytes> sent;
};

class DamageLog final : public ByteDevice {
 public:
  [[nodiscard]] LineSettings line_settings() const override { return {19200, 8, Parity::kEven, 1}; }
  void on_bytes(std::span<const std::uint8_t> bytes, TimePoint /*now*/) override {
    for (auto b : bytes) log.push_back(b);
  }
  void on_damaged_byte(std::uint8_t byte, TimePoint /*now*/) override {
    log.push_back(0x100 | byte);
  }
  void on_time(TimePoint /*now*/) override {}
  [[nodiscard]] std::optional<TimePoint> next_deadline() const override { return std::nullopt; }
  std::optional<std::vector<std::uint8_t>> take_transmit() override { return std::nullopt; }
  std::vector<unsigned> log;  // 0x1XX = XX received damaged
};

TEST(ByteRunnerDamaged, ADamagedCharacterReachesTheDeviceInLineOrder) {
  asio::io_context io;
  RealClock clock;
  ScriptedTransport transport;
  DamageLog device;
  ByteRunner runner(io, clock, transport);
  runner.add(device);
  runner.start();
  ASSERT_TRUE(transport.on_damaged_) << "the runner installs the handler before start()";
  transport.on_bytes_(Bytes{0x02, 0x01});
  transport.on_damaged_(0x0C);
  transport.on_bytes_(Bytes{0xF3});
  EXPECT_EQ(device.log, (std::vector<unsigned>{0x02, 0x01, 0x10C, 0xF3}));
  EXPECT_EQ(runner.counters().damaged_received, 1U);
  EXPECT_EQ(runner.counters().bytes_received, 3U);
  runner.stop();
}

TEST(ByteUdpTest, OneFramePerDatagram) {
  asio::io_context io;
  RealClock clock;
  const asio::ip::udp::endpoint any{asio::ip::make_address("127.0.0.1"), 0};
  UdpTransport device_side(io, any, any), client(io, any, any);
  device_side.set_peer(client.local_endpoint());
  client.set_peer(device_side.local_endpoint());
  EchoDevice echo{EchoOptions{k115200, 3.5, {}, 256}};
  ByteRunner runner(io, clock, device_side);
  runner.add(echo);
  runner.start();
  std::vector<Bytes> got;
  client.start([&](std::span<const std::uint8_t> b) { got.emplace_back(b.begin(), b.end()); }, {});
  client.send(Bytes{0x11, 0x22});
  ASSERT_TRUE(run_until(io, [&] { return got.size() == 1; }));
  EXPECT_EQ(got[0], (Bytes{0x11, 0x22}));
  EXPECT_EQ(runner.counters().chunks_received, 1U);
  runner.stop();
}

}  // namespace
}  // namespace rs4sim::stream
