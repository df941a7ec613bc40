// Turnaround statistics (dp/link/turnaround.h) and the StationRunner's reply path on the manual
// clock: a counting transport stands for the line, a station that takes a set time to answer
// stands for the core's processing, so every bound (the slot time, the buckets) is pinned on
// both sides without a wall clock.
#include "dp/link/turnaround.h"

#include "dp/link/station_runner.h"
#include "tests/dp/link/fake_station.h"

#include <gtest/gtest.h>

#include <vector>

namespace rs4sim::dp::link {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;
using testing::FakeStation;
using testing::srd_request;

TEST(TurnaroundBuckets, QuarterOctavesFrom1024Ns) {
  using T = TurnaroundStats;
  EXPECT_EQ(T::kBuckets, 102U);
  EXPECT_EQ(T::bucket_of(-5), 0U);
  EXPECT_EQ(T::bucket_of(0), 0U);
  EXPECT_EQ(T::bucket_of(1023), 0U);
  EXPECT_EQ(T::bucket_upper_ns(0), 1024);
  // 1024..1279 | 1280..1535 | 1536..1791 | 1792..2047 | 2048..2559 ...
  EXPECT_EQ(T::bucket_of(1024), 1U);
  EXPECT_EQ(T::bucket_of(1279), 1U);
  EXPECT_EQ(T::bucket_upper_ns(1), 1280);
  EXPECT_EQ(T::bucket_of(1280), 2U);
  EXPECT_EQ(T::bucket_of(1535), 2U);
  EXPECT_EQ(T::bucket_of(1536), 3U);
  EXPECT_EQ(T::bucket_of(2047), 4U);
  EXPECT_EQ(T::bucket_upper_ns(4), 2048);
  EXPECT_EQ(T::bucket_of(2048), 5U);
  EXPECT_EQ(T::bucket_upper_ns(5), 2560);
  // 1 ms = 1 000 000 ns: octave 19 (524 288..1 048 575), quarter 3 (917 504..1 048 575).
  EXPECT_EQ(T::bucket_of(1'000'000), 1U + 9 * 4 + 3);
  EXPECT_EQ(T::bucket_upper_ns(1 + 9 * 4 + 3), 1'048'576);
  // The last bounded bucket ends at 2^35 ns; from there on, the overflow bucket.
  EXPECT_EQ(T::bucket_of((std::int64_t{1} << 35) - 1), T::kBuckets - 2);
  EXPECT_EQ(T::bucket_upper_ns(T::kBuckets - 2), std::int64_t{1} << 35);
  EXPECT_EQ(T::bucket_of(std::int64_t{1} << 35), T::kBuckets - 1);
  EXPECT_EQ(T::bucket_of(INT64_MAX), T::kBuckets - 1);
}

TEST(TurnaroundStats, QuantilesAreBucketUpperBoundsCappedAtTheMaximum) {
  TurnaroundStats s;
  EXPECT_EQ(s.quantile_ns(0.5), 0);
  // 98 replies at 100 µs, one at 1 ms, one at 5 ms.
  for (int i = 0; i < 98; ++i) s.record(100us);
  s.record(1ms);
  s.record(5ms);
  EXPECT_EQ(s.count(), 100U);
  EXPECT_EQ(s.max_ns(), 5'000'000);
  EXPECT_EQ(s.mean_ns(), (98 * 100'000 + 1'000'000 + 5'000'000) / 100);
  // 100 000 ns: octave 16 (65 536..131 071), quarter 2 (98 304..114 687).
  EXPECT_EQ(s.quantile_ns(0.5), 114'688);
  EXPECT_EQ(s.quantile_ns(0.98), 114'688);
  EXPECT_EQ(s.quantile_ns(0.99), 1'048'576);  // rank 99: the 1 ms reply's bucket
  EXPECT_EQ(s.quantile_ns(1.0), 5'000'000);   // rank 100: the bucket's bound is above the max
  EXPECT_EQ(s.buckets()[TurnaroundStats::bucket_of(100'000)], 98U);
}

// A station that needs `processing` on the clock to answer a request (the clock moves while
// the runner waits for it, as the wall clock would).
class SlowStation final : public FakeStation {
 public:
  SlowStation(std::uint8_t address, ManualClock& clock)
      : FakeStation(address, Reply::kEchoData), clock_(clock) {}
  void on_telegram(const fdl::Telegram& t, TimePoint now) override {
    FakeStation::on_telegram(t, now);
    if (t.da == address()) clock_.advance(processing);
  }
  Duration processing{};

 private:
  ManualClock& clock_;
};

// The line: counts every send() and takes `write_time` on the clock for each.
class CountingTransport final : public Transport {
 public:
  explicit CountingTransport(ManualClock& clock) : clock_(clock) {}
  [[nodiscard]] bool datagram() const override { return false; }
  void start(BytesFn on_bytes, ErrorFn) override { deliver = std::move(on_bytes); }
  void send(std::span<const std::uint8_t> frame) override {
    sends.emplace_back(frame.begin(), frame.end());
    clock_.advance(write_time);
  }
  void close() override {}
  BytesFn deliver;
  std::vector<Bytes> sends;
  Duration write_time{};

 private:
  ManualClock& clock_;
};

Bytes wire(const fdl::Telegram& t) {
  Bytes b;
  fdl::encode(t, b);
  return b;
}

class RunnerTiming : public ::testing::Test {
 protected:
  void start(RunnerOptions options = {}) {
    runner.emplace(io, clock, transport, options);
    runner->add(slave);
    runner->start();
  }
  void request(std::uint8_t da = 5) { transport.deliver(wire(srd_request(da, 2, {0xA5}))); }

  boost::asio::io_context io;
  ManualClock clock;
  CountingTransport transport{clock};
  SlowStation slave{5, clock};
  std::optional<StationRunner> runner;
};

TEST_F(RunnerTiming, EachReplyIsOneSendTimedFromTheRequestReadToTheWritesReturn) {
  start();
  slave.processing = 300us;
  transport.write_time = 50us;
  request();
  ASSERT_EQ(transport.sends.size(), 1U);  // the whole telegram in one send
  // SD2 with one DU byte, DA 2, SA 5, FC 0x08 (DL) [IEC 61158-4-3 frame formats].
  EXPECT_EQ(transport.sends[0],
            (Bytes{0x68, 0x04, 0x04, 0x68, 0x02, 0x05, 0x08, 0xA5, 0xB4, 0x16}));
  slave.processing = 2ms;
  transport.write_time = 0us;
  request();
  const TurnaroundStats* t = runner->turnaround(5);
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(runner->turnaround(6), nullptr);
  EXPECT_EQ(t->count(), 2U);
  EXPECT_EQ(t->max_ns(), 2'000'000);
  EXPECT_EQ(t->mean_ns(), (350'000 + 2'000'000) / 2);
  EXPECT_EQ(t->buckets()[TurnaroundStats::bucket_of(350'000)], 1U);
  EXPECT_EQ(t->late(), 0U);
}

TEST_F(RunnerTiming, ARequestForAnotherStationAndTheMastersOwnSendsAreNotTimed) {
  start();
  request(7);  // not for station 5: no reply
  EXPECT_TRUE(transport.sends.empty());
  slave.send(srd_request(9, 5, {0x01}));  // a request of the station's own (a master's)
  io.poll();                              // the wake's drain
  EXPECT_EQ(transport.sends.size(), 1U);
  EXPECT_EQ(runner->turnaround(5)->count(), 0U);
}

TEST_F(RunnerTiming, AReplyLaterThanTheSlotTimeIsNotSentAndCountedAtTheBoundItIsSent) {
  RunnerOptions options;
  options.slot_time = 8ms;
  start(options);
  slave.processing = 8ms;  // leaves exactly at TSL: still in time
  request();
  EXPECT_EQ(transport.sends.size(), 1U);
  slave.processing = 8ms + 1us;  // the master's retry is already on the line
  request();
  EXPECT_EQ(transport.sends.size(), 1U);
  const TurnaroundStats& t = *runner->turnaround(5);
  EXPECT_EQ(t.count(), 1U);
  EXPECT_EQ(t.late(), 1U);
  EXPECT_EQ(t.max_ns(), 8'000'000);
  EXPECT_EQ(runner->counters().sent, 2U);  // both handed over by the station
}

TEST_F(RunnerTiming, WithoutTurnaroundTheRepliesStillGoOutUntimed) {
  RunnerOptions options;
  options.turnaround = false;
  start(options);
  slave.processing = 1ms;
  request();
  EXPECT_EQ(transport.sends.size(), 1U);
  EXPECT_EQ(runner->turnaround(5)->count(), 0U);
}

}  // namespace
}  // namespace rs4sim::dp::link
