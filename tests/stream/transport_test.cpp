// The transports of the byte-stream layer: serial configuration of any character format on a
// pseudo-terminal, typed errors of the serial port and of UDP endpoints.
#include "stream/pty.h"
#include "stream/serial_transport.h"
#include "stream/udp_transport.h"
#include "tests/stream/run_until.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace rs4sim::stream {
namespace {

namespace asio = boost::asio;

class PtyFormatTest : public ::testing::Test {
 protected:
  PseudoTerminal pty;
  std::vector<std::string> notes;
  LogFn log = [this](const std::string& s) { notes.push_back(s); };

  // Configures a fresh descriptor of the pty's slave side and returns what it kept.
  termios configure(const LineSettings& line, SerialSetup& setup) {
    const int fd = ::open(pty.slave_path().c_str(), O_RDWR | O_NOCTTY);
    EXPECT_GE(fd, 0);
    EXPECT_NO_THROW(setup = configure_serial(fd, line, "pty", log)) << to_string(line);
    termios back{};
    EXPECT_EQ(tcgetattr(fd, &back), 0);
    ::close(fd);
    return back;
  }
};

// A pty may not keep the parity or an exact rate (it has no line): whatever it refuses is a
// note, never an error, and every note went to the log.
TEST_F(PtyFormatTest, EveryFormatAndRateIsSetOrNoted) {
  const LineSettings lines[] = {
      {115200, 8, Parity::kNone, 1},  // GridScan [GridScan manual §9.1]
      {19200, 8, Parity::kEven, 1},   // METRON slave line mode [METRON manual "Slave line mode"]
      {9600, 7, Parity::kOdd, 2},      {1500000, 8, Parity::kEven, 1},
      {93750, 8, Parity::kEven, 1},  // no B-constant: termios2/BOTHER
      {12000000, 8, Parity::kEven, 1}, {250000, 8, Parity::kNone, 2},
  };
  for (const LineSettings& line : lines) {
    notes.clear();
    SerialSetup setup;
    (void)configure(line, setup);
    EXPECT_TRUE(setup.is_pty);
    EXPECT_EQ(setup.notes, notes) << to_string(line);
  }
}

// Whatever a pty does not take (Linux drops PARENB, some kernels refuse it with EINVAL) is no
// fault: at most one note per line, saying why, in words that do not read as an error.
TEST_F(PtyFormatTest, APtyGetsAtMostOneNoteThatReadsAsNoError) {
  const LineSettings lines[] = {
      {1500000, 8, Parity::kEven, 1}, {93750, 8, Parity::kEven, 1}, {9600, 7, Parity::kOdd, 2}};
  for (const LineSettings& line : lines) {
    notes.clear();
    SerialSetup setup;
    (void)configure(line, setup);
    ASSERT_LE(notes.size(), 1U) << to_string(line);
    for (const auto& n : notes) {
      EXPECT_EQ(n.rfind("pty: a pseudo-terminal has no wire, so no parity bit and no bit rate", 0),
                0U)
          << n;
      EXPECT_NE(n.find("nothing to fix"), std::string::npos) << n;
      EXPECT_EQ(n.find("failed"), std::string::npos) << n;
    }
  }
}

TEST_F(PtyFormatTest, EightNoneOneAndEightEvenOneReachTheTermiosFlags) {
  SerialSetup setup;
  const termios n81 = configure({115200, 8, Parity::kNone, 1}, setup);
  EXPECT_EQ(n81.c_cflag & CSIZE, static_cast<tcflag_t>(CS8));
  EXPECT_EQ(n81.c_cflag & PARENB, 0U);
  EXPECT_EQ(n81.c_cflag & CSTOPB, 0U);
  EXPECT_EQ(cfgetospeed(&n81), static_cast<speed_t>(B115200));
  const termios e81 = configure({19200, 8, Parity::kEven, 1}, setup);
  EXPECT_EQ(e81.c_cflag & CSIZE, static_cast<tcflag_t>(CS8));
  EXPECT_EQ(cfgetospeed(&e81), static_cast<speed_t>(B19200));
  // Linux ptys keep PARENB; should one not, configure_serial noted it instead of failing.
  if ((e81.c_cflag & PARENB) == 0) {
    EXPECT_FALSE(setup.notes.empty());
  } else {
    EXPECT_EQ(e81.c_cflag & PARODD, 0U);
    EXPECT_NE(e81.c_iflag & INPCK, 0U);
  }
}

TEST(SerialTransportErrors, MissingDeviceAndNonTerminalAreTypedErrors) {
  asio::io_context io;
  const LineSettings line{19200, 8, Parity::kEven, 1};
  try {
    SerialTransport t(io, "/nonexistent/ttyRS485", line);
    FAIL() << "opened a missing device";
  } catch (const LinkException& e) {
    EXPECT_EQ(e.code(), LinkError::kOpenFailed);
    EXPECT_STREQ(e.code().category().name(), "stream.link");
    EXPECT_NE(std::string(e.what()).find("/nonexistent/ttyRS485"), std::string::npos);
  }
  try {
    SerialTransport t(io, "/dev/null", line);
    FAIL() << "/dev/null taken as a serial port";
  } catch (const LinkException& e) {
    EXPECT_EQ(e.code(), LinkError::kNotATerminal);
  }
}

TEST(UdpEndpoint, BadEndpointsAreTypedErrors) {
  asio::io_context io;
  for (const char* bad : {"127.0.0.1", ":5000", "127.0.0.1:", "127.0.0.1:99999", "127.0.0.1:x1",
                          "no-such-host.invalid:5000"}) {
    try {
      (void)resolve_udp_endpoint(io, bad);
      ADD_FAILURE() << bad;
    } catch (const LinkException& e) {
      EXPECT_EQ(e.code(), LinkError::kBadEndpoint) << bad;
    }
  }
  const auto ep = resolve_udp_endpoint(io, "localhost:5000");
  EXPECT_EQ(ep.port(), 5000);
  EXPECT_TRUE(ep.address().is_loopback());
  EXPECT_EQ(resolve_udp_endpoint(io, "[::1]:7").address().to_string(), "::1");
}

TEST(UdpEndpoint, PortInUseIsABindError) {
  asio::io_context io;
  const asio::ip::udp::endpoint any{asio::ip::make_address("127.0.0.1"), 0};
  UdpTransport first(io, any, any);
  try {
    UdpTransport second(io, first.local_endpoint(), any);
    FAIL() << "bound the same port twice";
  } catch (const LinkException& e) {
    EXPECT_EQ(e.code(), LinkError::kBindFailed);
  }
}

// PROFIBUS allows no idle time between a telegram's characters [IEC 61158-4-3 UART character]:
// each frame goes to the kernel in one write(), so the reader on the other side of the pty
// finds it whole in one read, and the transport counts it as written whole.
class OneWritePerTelegram : public ::testing::Test {
 protected:
  asio::io_context io;
  PseudoTerminal pty;
  int reader = -1;
  void SetUp() override {
    // Non-blocking: a frame not yet written fails the read instead of hanging the test.
    reader = ::open(pty.slave_path().c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
    ASSERT_GE(reader, 0);
  }
  void TearDown() override {
    if (reader >= 0) ::close(reader);
  }
};

TEST_F(OneWritePerTelegram, EveryFrameArrivesInOneReadAndIsCountedWhole) {
  SerialTransport t(io, pty.release_master(), {1500000, 8, Parity::kEven, 1}, "pty");
  t.start([](std::span<const std::uint8_t>) {}, [](std::error_code) {});
  for (std::size_t size : {1U, 6U, 14U, 255U}) {
    std::vector<std::uint8_t> frame(size);
    for (std::size_t i = 0; i < size; ++i) frame[i] = static_cast<std::uint8_t>(i + size);
    t.send(frame);
    // send() returned: the bytes are already in the kernel, before the loop has run at all.
    std::vector<std::uint8_t> got(512);
    const ssize_t n = ::read(reader, got.data(), got.size());
    ASSERT_EQ(n, static_cast<ssize_t>(size));
    got.resize(size);
    EXPECT_EQ(got, frame);
  }
  EXPECT_EQ(t.write_counters().frames, 4U);
  EXPECT_EQ(t.write_counters().whole, 4U);
  EXPECT_EQ(t.write_counters().split, 0U);
}

// A stalled line (nobody reads, the pty's buffer fills up): the frame that does not fit is
// the only one written in parts; it and the frames behind it follow in order once the reader
// drains.
TEST_F(OneWritePerTelegram, AFullKernelBufferSplitsAFrameAndKeepsTheOrder) {
  SerialTransport t(io, pty.release_master(), {1500000, 8, Parity::kEven, 1}, "pty");
  t.start([](std::span<const std::uint8_t>) {}, [](std::error_code) {});
  std::vector<std::uint8_t> sent;
  std::uint8_t next = 0;
  int frames = 0;
  while (t.write_counters().split < 2 && frames < 100000) {
    std::vector<std::uint8_t> frame(255);
    for (auto& b : frame) b = next++;
    sent.insert(sent.end(), frame.begin(), frame.end());
    t.send(frame);
    ++frames;
  }
  ASSERT_EQ(t.write_counters().split, 2U);  // the first that did not fit, one queued behind it
  EXPECT_EQ(t.write_counters().whole, static_cast<std::uint64_t>(frames - 2));
  std::vector<std::uint8_t> got;
  ASSERT_TRUE(stream::testing::run_until(io, [&] {
    std::uint8_t buf[4096];
    for (ssize_t n; (n = ::read(reader, buf, sizeof buf)) > 0;) got.insert(got.end(), buf, buf + n);
    return got.size() >= sent.size();
  }));
  EXPECT_EQ(got, sent);
  EXPECT_EQ(t.write_counters().errors, 0U);
}

// The adapter setup (stream/serial_adapter.h) on a pty, where the serial ioctls fail as they do
// on any tty without them, with the sysfs tree of a USB adapter in a temporary directory.
class AdapterSetupTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root = std::filesystem::temp_directory_path() /
           ("rs4sim-sysfs-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(root / "bus/usb-serial/devices/ttyUSB7");
    std::filesystem::create_directories(root / "class/tty/ttyUSB7/device");
    std::filesystem::create_directories(root / "bus/usb-serial/drivers/ftdi_sio");
    std::filesystem::create_directory_symlink(root / "bus/usb-serial/drivers/ftdi_sio",
                                              root / "class/tty/ttyUSB7/device/driver");
    fd = ::open(pty.slave_path().c_str(), O_RDWR | O_NOCTTY);
    ASSERT_GE(fd, 0);
  }
  void TearDown() override {
    ::close(fd);
    std::filesystem::remove_all(root);
  }
  std::filesystem::path latency() const {
    return root / "bus/usb-serial/devices/ttyUSB7/latency_timer";
  }
  PseudoTerminal pty;
  std::filesystem::path root;
  int fd = -1;
  std::vector<std::string> notes;
  LogFn log = [this](const std::string& s) { notes.push_back(s); };
};

TEST_F(AdapterSetupTest, TheFtdiLatencyTimerIsSetTo1MsAndNothingIsNoted) {
  std::ofstream(latency()) << "16\n";
  const AdapterSetup a = tune_adapter(fd, "ttyUSB7", log, root.string());
  EXPECT_EQ(a.driver, "ftdi_sio");
  EXPECT_EQ(a.latency_timer_ms, 1);
  EXPECT_FALSE(a.async_low_latency);  // TIOCGSERIAL fails on a pty
  EXPECT_TRUE(a.low_latency());
  EXPECT_FALSE(a.rs485);  // ENOTTY on a pty: not used, not mentioned
  EXPECT_TRUE(notes.empty()) << notes.front();
  std::ifstream in(latency());
  int ms = 0;
  in >> ms;
  EXPECT_EQ(ms, 1);
  EXPECT_EQ(read_adapter(fd, "ttyUSB7", root.string()).latency_timer_ms, 1);
}

TEST_F(AdapterSetupTest, ALatencyTimerThatCannotBeWrittenIsNotedWithItsValue) {
  // A directory where the file should be: reading and writing it fail.
  std::filesystem::create_directory(latency());
  const AdapterSetup a = tune_adapter(fd, "ttyUSB7", log, root.string());
  EXPECT_FALSE(a.low_latency());
  ASSERT_EQ(notes.size(), 1U);
  EXPECT_NE(notes[0].find("/dev/ttyUSB7 (ftdi_sio): low-latency mode not set (writing 1 to"),
            std::string::npos)
      << notes[0];
  EXPECT_EQ(a.notes, notes);
}

TEST_F(AdapterSetupTest, WithoutSysfsEntriesTheFailedIoctlIsTheNote) {
  const AdapterSetup a = tune_adapter(fd, "ttyS9", log, root.string());
  EXPECT_EQ(a.driver, "");
  EXPECT_EQ(a.latency_timer_ms, std::nullopt);
  ASSERT_EQ(notes.size(), 1U);
  EXPECT_NE(notes[0].find("/dev/ttyS9: low-latency mode not set (TIOCGSERIAL: "), std::string::npos)
      << notes[0];
}

TEST(RateDeviation, RelativeToTheAskedRate) {
  EXPECT_DOUBLE_EQ(rate_deviation(187500, 187500), 0.0);
  EXPECT_DOUBLE_EQ(rate_deviation(500000, 500000 + 1500), 0.003);
  EXPECT_DOUBLE_EQ(rate_deviation(187500, 230400), 42900.0 / 187500.0);
}

}  // namespace
}  // namespace rs4sim::stream
