// Fault injection on the in-memory bus: lost and corrupted telegrams are retried
// ([IEC 61158-4-3 FCB/FCV], [IEC 61158-6-3 slave supervision]), a silent slave is reported lost and
// comes back, and the slave watchdog ([IEC 61158-6-3 watchdog]) drops a slave whose master falls
// silent; all on the manual clock.
#include "dp/master/master_error.h"
#include "tests/integration/bus_helpers.h"

#include <gtest/gtest.h>

namespace rs4sim::integration {
namespace {

using dp::link::Fault;
using dp::link::FaultKind;

class FaultIntegration : public ::testing::Test {
 protected:
  static GenericBusConfig config() {
    GenericBusConfig c;
    c.master_address = 1;
    c.slaves = {slave_config(5), slave_config(6), slave_config(7)};
    return c;
  }
  void SetUp() override {
    ASSERT_TRUE(b.run_until([&] { return b.slaves_in_data_exchange() == 3; }, 2s));
    b.take_events();
  }
  std::uint64_t retries(std::uint8_t a) { return b.master().slave_status(a)->counters.retries; }
  GenericBus b{config()};
};

TEST_F(FaultIntegration, ADroppedRequestIsRetriedAndTheSlaveStays) {
  const auto before = retries(6);
  b.bus().inject({FaultKind::kDrop, 1, 6, 1});
  b.run_for(100ms);
  EXPECT_EQ(retries(6), before + 1);
  EXPECT_EQ(b.bus().counters(1).dropped, 1U);
  EXPECT_EQ(b.slaves_in_data_exchange(), 3U);
  EXPECT_EQ(count_events<dp::master::SlaveLeftDataExchange>(b.events(), 6), 0U);
}

TEST_F(FaultIntegration, ADroppedReplyIsRetriedAndTheRepeatIsNotExecutedTwice) {
  const auto before = retries(5);
  const auto exchanges = b.slave(5).device().exchanges();
  b.bus().inject({FaultKind::kDrop, 5, 1, 1});
  b.run_for(100ms);
  EXPECT_EQ(retries(5), before + 1);
  // The repeated Data_Exchange (same FCB) is answered from the stored reply
  // ([IEC 61158-4-3 FCB/FCV]).
  EXPECT_GE(b.slave(5).slave().counters().repeats_answered, 1U);
  EXPECT_GE(b.slave(5).device().exchanges(), exchanges);
  EXPECT_EQ(b.slaves_in_data_exchange(), 3U);
}

TEST_F(FaultIntegration, ACorruptedRequestIsRejectedByTheSlaveDecoderAndRetried) {
  const auto before = retries(7);
  b.bus().inject({FaultKind::kCorrupt, 1, 7, 1, {}, 5 * 8 + 2});  // a bit in SA / FC area
  b.run_for(100ms);
  EXPECT_EQ(b.bus().counters(7).malformed, 1U);
  EXPECT_EQ(b.slave(7).slave().counters().malformed_dropped, 1U);  // on_malformed_frame()
  EXPECT_EQ(b.bus().counters(1).corrupted, 1U);
  EXPECT_EQ(retries(7), before + 1);
  EXPECT_EQ(b.slaves_in_data_exchange(), 3U);
}

TEST_F(FaultIntegration, ASilencedSlaveIsLostThenRecovers) {
  b.bus().set_silenced(6, true);
  ASSERT_TRUE(b.run_until([&] { return b.slaves_in_data_exchange() == 2; }, 1s));
  const auto* left = last_event<dp::master::SlaveLeftDataExchange>(b.events());
  ASSERT_NE(left, nullptr);
  EXPECT_EQ(left->address, 6);
  EXPECT_EQ(left->reason, dp::master::MasterError::kNoAnswer);
  // The silent slave's watchdog (100 ms) expires too: it is back in Wait_Prm.
  b.run_for(200ms);
  EXPECT_EQ(b.slave(6).slave().state(), dp::slave::State::kWaitPrm);
  EXPECT_EQ(b.slave(6).slave().counters().watchdog_expiries, 1U);
  b.bus().set_silenced(6, false);
  ASSERT_TRUE(b.run_until([&] { return b.slaves_in_data_exchange() == 3; }, 2s));
  EXPECT_EQ(count_events<dp::master::SlaveEnteredDataExchange>(b.events(), 6), 1U);
  EXPECT_EQ(b.slave(6).slave().state(), dp::slave::State::kDataExch);
}

TEST_F(FaultIntegration, WatchdogDropsSlavesWhenTheMasterFallsSilentAndTheyComeBack) {
  b.bus().set_silenced(1, true);
  const TimePoint t0 = b.clock().now();
  ASSERT_TRUE(
      b.run_until([&] { return b.slave(5).slave().state() == dp::slave::State::kWaitPrm; }, 1s));
  // T_WD = 100 ms after the last telegram the slave received ([IEC 61158-6-3 watchdog]).
  EXPECT_LE(b.clock().now() - t0, 100ms);
  EXPECT_GE(b.clock().now() - t0, 85ms);
  EXPECT_EQ(b.slave(5).device().state(), dp::slave::State::kWaitPrm);
  b.bus().set_silenced(1, false);
  ASSERT_TRUE(b.run_until(
      [&] {
        return b.slaves_in_data_exchange() == 3 &&
               b.slave(5).slave().state() == dp::slave::State::kDataExch;
      },
      2s));
}

TEST_F(FaultIntegration, AConstantReplyDelayWithinTheSlotTimeIsHarmless) {
  // 1 µs extra on every reply of slave 7: well inside TSL (1000 bit = 83 µs at 12M).
  b.bus().inject({FaultKind::kDelay, 7, 1, 0, 1us});
  b.run_for(500ms);
  EXPECT_GT(b.bus().counters(7).delayed, 10U);
  EXPECT_EQ(b.slaves_in_data_exchange(), 3U);
}

}  // namespace
}  // namespace rs4sim::integration
