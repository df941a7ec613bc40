// MemoryBus: routing, simulated time, wire model and fault injection.
// Known answers are the worked example of [docs/references.md#dp-worked-example] and the timing
// rules of [IEC 61158-4-3 UART character, bus parameters, timing] [IEC 61158-2 baud rates].
#include "dp/link/memory_bus.h"

#include "tests/dp/link/fake_station.h"

#include <gtest/gtest.h>

namespace rs4sim::dp::link {
namespace {

using namespace std::chrono_literals;
using namespace testing;  // FakeStation, srd_request
using Bytes = std::vector<std::uint8_t>;

struct Wire {
  std::uint8_t from;
  std::optional<std::uint8_t> to;
  Bytes bytes;
  Fate fate;
  TimePoint time, arrival;
};

class MemoryBusTest : public ::testing::Test {
 protected:
  void SetUp() override {
    bus.add_observer([this](const BusEvent& e) {
      log.push_back({e.from, e.to, Bytes(e.wire.begin(), e.wire.end()), e.fate, e.time, e.arrival});
    });
  }
  ManualClock clock;
  MemoryBus bus{clock};
  std::vector<Wire> log;
};

TEST_F(MemoryBusTest, DataExchangeOfSpecExampleIsRoutedAndAnswered) {
  FakeStation master(2);
  FakeStation slave(5, FakeStation::Reply::kEchoData);
  slave.reply_data = Bytes{0x3C};
  bus.attach(master);
  bus.attach(slave);
  master.outbox.push_back(srd_request(5, 2, {0xA5}));
  bus.start();
  while (bus.step()) {
  }
  ASSERT_EQ(log.size(), 2U);
  // [docs/references.md#dp-worked-example] "M→S DX": 68 04 04 68 05 02 7D A5 29 16
  const Bytes request = {
      0x68,  // 0 SD2
      0x04,  // 1 LE = DA+SA+FC+DU
      0x04,  // 2 LEr
      0x68,  // 3 SD2 repeated
      0x05,  // 4 DA = slave 5
      0x02,  // 5 SA = master 2
      0x7D,  // 6 FC: request, FCB=1, FCV=1, SRD high
      0xA5,  // 7 DU: output byte
      0x29,  // 8 FCS = 05+02+7D+A5 mod 256
      0x16,  // 9 ED
  };
  EXPECT_EQ(log[0].bytes, request);
  EXPECT_EQ(log[0].to, 5);
  // [docs/references.md#dp-worked-example] "S→M DX reply DL": 68 04 04 68 02 05 08 3C 4B 16
  const Bytes reply = {
      0x68, 0x04, 0x04, 0x68,  // 0..3 SD2 LE LEr SD2
      0x02,                    // 4 DA = master 2
      0x05,                    // 5 SA = slave 5
      0x08,                    // 6 FC: response, slave, DL
      0x3C,                    // 7 DU: input byte
      0x4B,                    // 8 FCS
      0x16,                    // 9 ED
  };
  EXPECT_EQ(log[1].bytes, reply);
  EXPECT_EQ(log[1].to, 2);
  ASSERT_EQ(master.received.size(), 1U);
  EXPECT_EQ(master.received[0].telegram.data[0], 0x3C);
  EXPECT_EQ(bus.counters(2).sent, 1U);
  EXPECT_EQ(bus.counters(5).received, 1U);
  EXPECT_EQ(bus.counters(2).received, 1U);
}

TEST_F(MemoryBusTest, ShortAckGoesToTheRequesterAndAStrayReplyIsUnroutable) {
  FakeStation master(1), other(3), slave(9, FakeStation::Reply::kShortAck);
  bus.attach(master);
  bus.attach(other);
  bus.attach(slave);
  master.outbox.push_back(srd_request(9, 1, {0x00}));
  bus.start();
  while (bus.step()) {
  }
  ASSERT_EQ(master.received.size(), 1U);
  EXPECT_EQ(master.received[0].telegram.type, fdl::FrameType::kShortAck);
  EXPECT_TRUE(other.received.empty());
  // A second reply without a new request has nobody to go to.
  slave.run_timer(clock.now() + 1ms, 1h, fdl::make_short_ack());
  bus.run_for(2ms);
  EXPECT_EQ(slave.timer_fires, 1);
  EXPECT_EQ(bus.counters(9).unroutable, 1U);
  EXPECT_EQ(master.received.size(), 1U);
  EXPECT_EQ(log.back().fate, Fate::kUnroutable);
}

TEST_F(MemoryBusTest, BroadcastReachesEveryOtherStationAndIsNeverAnswered) {
  FakeStation master(2);
  std::vector<std::unique_ptr<FakeStation>> slaves;
  bus.attach(master);
  for (std::uint8_t a = 3; a < 8; ++a) {
    slaves.push_back(std::make_unique<FakeStation>(a, FakeStation::Reply::kShortAck));
    bus.attach(*slaves.back());
  }
  // [docs/references.md#dp-worked-example] "M→* GC Clear": SDN high to DA 127, DSAP 58, SSAP 62, DU
  // 02 00.
  master.outbox.push_back(fdl::make_data_telegram(
      127, 2, fdl::FrameControl::request(fdl::RequestFunction::kSdnHigh, false, false), 58, 62,
      Bytes{0x02, 0x00}));
  bus.start();
  while (bus.step()) {
  }
  const Bytes gc = {0x68, 0x07, 0x07, 0x68, 0xFF, 0x82, 0x46, 0x3A, 0x3E, 0x02, 0x00, 0x41, 0x16};
  ASSERT_EQ(log.size(), 1U);  // no station answered
  EXPECT_EQ(log[0].bytes, gc);
  EXPECT_EQ(log[0].to, 127);
  for (auto& s : slaves) EXPECT_EQ(s->received.size(), 1U) << int(s->address());
  EXPECT_TRUE(master.received.empty());
}

TEST_F(MemoryBusTest, ThirtySecondsOfTimersRunOnTheManualClockInOrder) {
  FakeStation a(1), b(2);
  bus.attach(a);
  bus.attach(b);
  const TimePoint t0 = clock.now();
  a.run_timer(t0 + 10ms, 10ms);
  b.run_timer(t0 + 10ms, 30ms);
  bus.start();
  bus.run_until(t0 + 30s);
  EXPECT_EQ(a.timer_fires, 3000);
  EXPECT_EQ(b.timer_fires, 1000);
  EXPECT_EQ(clock.now(), t0 + 30s);
  EXPECT_EQ(a.last_on_time, t0 + 30s);
}

TEST_F(MemoryBusTest, StepJumpsToTheEarliestDeadline) {
  FakeStation a(1);
  bus.attach(a);
  const TimePoint t0 = clock.now();
  a.run_timer(t0 + 250ms, 1s);
  EXPECT_EQ(bus.next_event_time(), t0 + 250ms);
  ASSERT_TRUE(bus.step());
  EXPECT_EQ(clock.now(), t0 + 250ms);
  EXPECT_EQ(a.timer_fires, 1);
  EXPECT_EQ(bus.next_event_time(), t0 + 1250ms);
}

// A deadline that moves later while another station is at the front is written to the
// deadline tree only when its old entry comes to the front (MemoryBus::refresh_deadline): the
// order of the deadlines and the tie-break (the station attached first) stay exact.
TEST_F(MemoryBusTest, DeadlinesThatMoveLaterFireInOrderAndTiesGoToTheFirstAttached) {
  FakeStation a(1), b(2);
  bus.attach(a);
  bus.attach(b);
  bus.start();
  const TimePoint t0 = clock.now();
  log.clear();
  a.run_timer(t0 + 10ms, 10ms, fdl::make_token(1, 1));
  b.run_timer(t0 + 5ms, 25ms, fdl::make_token(2, 2));  // b: 5, 30, 55 ms
  a.run_timer(t0 + 30ms, 25ms, fdl::make_token(1, 1));  // later, b at the front: 30, 55 ms
  EXPECT_EQ(bus.next_event_time(), t0 + 5ms);
  bus.run_until(t0 + 60ms);
  std::vector<std::pair<std::uint8_t, Duration>> sent;
  for (const Wire& w : log) {
    if (w.from == w.to) sent.emplace_back(w.from, w.time - t0);  // the timer tokens
  }
  const std::vector<std::pair<std::uint8_t, Duration>> expected = {
      {2, 5ms}, {1, 30ms}, {2, 30ms}, {1, 55ms}, {2, 55ms}};
  EXPECT_EQ(sent, expected);
  EXPECT_EQ(bus.next_event_time(), t0 + 80ms);
}

TEST_F(MemoryBusTest, AStationThatNeverAdvancesItsDeadlineIsReported) {
  FakeStation a(4);
  a.stuck_deadline = clock.now();
  bus.attach(a);
  EXPECT_THROW(bus.run_for(1s), std::logic_error);
}

TEST_F(MemoryBusTest, AttachRejectsBadAndDuplicateAddresses) {
  FakeStation a(5), dup(5), bad(127);
  bus.attach(a);
  EXPECT_THROW(bus.attach(dup), std::invalid_argument);
  EXPECT_THROW(bus.attach(bad), std::invalid_argument);
  EXPECT_THROW((void)bus.counters(6), std::out_of_range);
}

}  // namespace
}  // namespace rs4sim::dp::link
