// StationRunner over a pseudo-terminal pair and over UDP on localhost, with fake stations
// (the transports' own tests: tests/stream/transport_test.cpp).
// Real time: every wait is bounded (generous timeout) and ends as soon as the condition
// holds; no fixed sleep decides a result.
#include "dp/link/profibus_line.h"
#include "dp/link/station_runner.h"
#include "stream/pty.h"
#include "stream/serial_transport.h"
#include "stream/udp_transport.h"
#include "tests/dp/link/fake_station.h"
#include "tests/stream/run_until.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <functional>

namespace rs4sim::dp::link {
namespace {

using namespace std::chrono_literals;
using namespace testing;  // FakeStation, srd_request
using Bytes = std::vector<std::uint8_t>;
using stream::LogFn;
using stream::PseudoTerminal;
using stream::SerialTransport;
using stream::UdpTransport;
namespace asio = boost::asio;

using stream::testing::run_until;

class PtyLinkTest : public ::testing::Test {
 protected:
  asio::io_context io;
  RealClock clock;
  PseudoTerminal pty;
  std::vector<std::string> notes;
  LogFn log = [this](const std::string& s) { notes.push_back(s); };
};

TEST_F(PtyLinkTest, MasterAndSlaveExchangeOverThePtyPair) {
  SerialTransport slave_side(io, pty.release_master(), profibus_line(BaudRate::k12M), "pty master",
                             log);
  SerialTransport master_side(io, pty.slave_path(), profibus_line(BaudRate::k19k2), log);
  EXPECT_TRUE(slave_side.setup().is_pty);
  EXPECT_TRUE(master_side.setup().is_pty);
  FakeStation slave(5, FakeStation::Reply::kEchoData), master(2);
  slave.reply_data = Bytes{0x3C};
  StationRunner slave_runner(io, clock, slave_side), master_runner(io, clock, master_side);
  slave_runner.add(slave);
  master_runner.add(master);
  master.outbox.push_back(srd_request(5, 2, {0xA5}));
  slave_runner.start();
  master_runner.start();
  ASSERT_TRUE(run_until(io, [&] { return !master.received.empty(); }));
  EXPECT_EQ(slave.received.at(0).telegram.data[0], 0xA5);
  EXPECT_EQ(master.received[0].telegram.data[0], 0x3C);
  EXPECT_EQ(master.received[0].telegram.fc.status(), fdl::ResponseStatus::kDataLow);
  EXPECT_EQ(master_runner.counters().sent, 1U);
  EXPECT_EQ(slave_runner.counters().received, 1U);
  EXPECT_EQ(slave_runner.counters().malformed, 0U);
  slave_runner.stop();
  master_runner.stop();
}

TEST_F(PtyLinkTest, GarbageAndATruncatedFrameAreDroppedAndCountedThenFramingRecovers) {
  SerialTransport slave_side(io, pty.release_master(), profibus_line(BaudRate::k1M5), "pty master",
                             log);
  FakeStation slave(5);
  RunnerOptions options;
  options.idle_gap = 20ms;
  StationRunner runner(io, clock, slave_side, options);
  runner.add(slave);
  runner.start();
  const int fd = ::open(pty.slave_path().c_str(), O_RDWR | O_NOCTTY);
  ASSERT_GE(fd, 0);
  // Noise, then the first 6 bytes of an SD2 frame that never completes (line goes idle).
  const Bytes noise = {0x00, 0xFF, 0x42, 0x68, 0x04, 0x04, 0x68, 0x05, 0x02};
  ASSERT_EQ(::write(fd, noise.data(), noise.size()), static_cast<ssize_t>(noise.size()));
  ASSERT_TRUE(run_until(
      io, [&] { return runner.decoder_stats().count(fdl::DecodeError::kTruncated) == 1; }));
  // [docs/references.md#dp-worked-example] "M→S DX" arrives whole after the idle gap and is
  // delivered.
  const Bytes dx = {0x68, 0x04, 0x04, 0x68, 0x05, 0x02, 0x7D, 0xA5, 0x29, 0x16};
  ASSERT_EQ(::write(fd, dx.data(), dx.size()), static_cast<ssize_t>(dx.size()));
  ASSERT_TRUE(run_until(io, [&] { return slave.received.size() == 1; }));
  EXPECT_EQ(slave.received[0].telegram.data[0], 0xA5);
  EXPECT_GE(runner.counters().malformed, 2U);  // garbage + truncated frame
  ::close(fd);
  runner.stop();
}

TEST_F(PtyLinkTest, EveryStandardRateIsSetOrNotedOnAPty) {
  for (BaudRate b : kStandardBaudRates) {
    notes.clear();
    const int fd = ::open(pty.slave_path().c_str(), O_RDWR | O_NOCTTY);
    ASSERT_GE(fd, 0);
    stream::SerialSetup setup;
    EXPECT_NO_THROW(setup = configure_profibus_serial(fd, b, "pty", log)) << to_string(b);
    EXPECT_TRUE(setup.is_pty);
    EXPECT_EQ(setup.notes, notes);  // every refusal was logged
    ::close(fd);
  }
}

class UdpLinkTest : public ::testing::Test {
 protected:
  asio::io_context io;
  RealClock clock;
  asio::ip::udp::endpoint any{asio::ip::make_address("127.0.0.1"), 0};
};

TEST_F(UdpLinkTest, OneDatagramPerTelegramBothWays) {
  UdpTransport a(io, any, any), b(io, any, any);
  a.set_peer(b.local_endpoint());
  b.set_peer(a.local_endpoint());
  FakeStation master(2), slave(5, FakeStation::Reply::kShortAck);
  StationRunner ra(io, clock, a), rb(io, clock, b);
  ra.add(master);
  rb.add(slave);
  master.outbox.push_back(srd_request(5, 2, {0x01, 0x02}));
  ra.start();
  rb.start();
  ASSERT_TRUE(run_until(io, [&] { return !master.received.empty(); }));
  EXPECT_EQ(master.received[0].telegram.type, fdl::FrameType::kShortAck);
  EXPECT_EQ(slave.received.at(0).telegram.data.size(), 2U);
  ra.stop();
  rb.stop();
}

TEST_F(UdpLinkTest, ForeignSendersAndMalformedDatagramsAreCounted) {
  UdpTransport a(io, any, any), b(io, any, any), stranger(io, any, any);
  b.set_peer(a.local_endpoint());
  a.set_peer(b.local_endpoint());
  stranger.set_peer(b.local_endpoint());
  FakeStation slave(5);
  StationRunner rb(io, clock, b);
  rb.add(slave);
  rb.start();
  // From the stranger: dropped before decoding.
  const Bytes dx = {0x68, 0x04, 0x04, 0x68, 0x05, 0x02, 0x7D, 0xA5, 0x29, 0x16};
  stranger.start({}, {});
  stranger.send(dx);
  ASSERT_TRUE(run_until(io, [&] { return b.foreign_datagrams() == 1; }));
  // From the peer: a bad FCS (0x28) and a truncated frame, then the good one.
  a.start({}, {});
  Bytes bad = dx;
  bad[8] = 0x28;
  a.send(bad);
  a.send(std::span(dx).first(6));
  a.send(dx);
  ASSERT_TRUE(run_until(io, [&] { return slave.received.size() == 1; }));
  EXPECT_EQ(rb.counters().malformed, 2U);
  EXPECT_EQ(rb.decoder_stats().count(fdl::DecodeError::kBadFcs), 1U);
  EXPECT_EQ(rb.decoder_stats().count(fdl::DecodeError::kTruncated), 1U);
  rb.stop();
}

TEST_F(UdpLinkTest, RunnerFiresStationDeadlines) {
  UdpTransport a(io, any, any);
  FakeStation s(3);
  StationRunner r(io, clock, a);
  r.add(s);
  s.run_timer(clock.now() + 5ms, 5ms);
  r.start();
  ASSERT_TRUE(run_until(io, [&] { return s.timer_fires >= 3; }));
  EXPECT_GE(s.last_on_time, clock.now() - 10s);
  r.stop();
}

}  // namespace
}  // namespace rs4sim::dp::link
