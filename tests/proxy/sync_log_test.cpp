// What the proxy writes into the archive says what happened and when: the sync log's direction
// is the transfer done, not the one the RS4 asked for (a first commissioning with nothing
// stored downloads nothing), and a version's time is the wall clock at the write, with a
// simulated run's own time beside it (docs/storage.md "Times", docs/proxy.md).
#include "tests/proxy/sync_harness.h"

#include <gtest/gtest.h>

namespace rs4sim::proxy::testing {
namespace {

using rs4::protocol::SyncDirection;

// 2025-12-01T12:00:00Z, the wall clock the owner injects; the simulated clock starts at 1 h.
constexpr storage::Timestamp kWall{std::chrono::milliseconds{1'764'590'400'000}};
constexpr dp::TimePoint kSimStart{std::chrono::hours{1}};

std::vector<storage::SyncLogEntry> log_of(SyncHarness& h) {
  return h.real->sync_log(SyncHarness::kStation, 10).value();
}

// Issue: "download succeeded" for the first sync of a factory-new RS4 with nothing stored.
TEST(SyncLog, AFirstCommissioningWithNothingStoredLogsNoTransfer) {
  SyncHarness h;
  h.device.factory = true;
  h.device.direction = SyncDirection::kDownload;  // what the RS4 asks for
  ASSERT_TRUE(h.run_sync());
  const auto log = log_of(h);
  ASSERT_EQ(log.size(), 1u);
  EXPECT_EQ(log[0].direction, storage::SyncDirection::kNone);
  EXPECT_EQ(log[0].outcome, storage::SyncOutcome::kSucceeded);
}

TEST(SyncLog, AFactoryDeviceThatGetsTheStoredSetLogsADownload) {
  SyncHarness h;
  h.store_for_a_factory_device();
  ASSERT_TRUE(h.run_sync());
  const auto log = log_of(h);
  ASSERT_EQ(log.size(), 1u);
  EXPECT_EQ(log[0].direction, storage::SyncDirection::kDownload);
}

// Issue: the demo stamped versions "wall clock at start + simulated time", up to 70 s in the
// future. With the wall clock read at the write, a version is dated by that reading, and the
// simulated time sits beside it.
TEST(SyncTimes, AVersionIsDatedByTheWallClockAtTheWriteWithTheSimulatedTimeBeside) {
  SyncHarness h;
  int reads = 0;
  h.config.wall_clock = [&reads] {
    ++reads;
    return kWall;
  };
  h.config.simulated = true;
  h.sync = std::make_unique<ProxySync>(h.config, h.archive);
  h.now = kSimStart;
  h.device.set = SyncHarness::custom_set(5);
  h.device.direction = SyncDirection::kUpload;
  ASSERT_TRUE(h.run_sync());
  const auto v = h.real->current(SyncHarness::kStation).value().version;
  EXPECT_EQ(v.at, kWall);  // not kWall + 1 h + the sync's time
  ASSERT_TRUE(v.simulated);
  EXPECT_GT(*v.simulated, std::chrono::milliseconds{3'600'000});  // during the sync ...
  EXPECT_LE(*v.simulated, std::chrono::duration_cast<std::chrono::milliseconds>(
                              h.now.time_since_epoch()));  // ... not after its end
  EXPECT_GE(reads, 1);
}

TEST(SyncTimes, ARealDevicesVersionHasNoSimulatedTime) {
  SyncHarness h;
  h.config.wall_clock = [] { return kWall; };
  h.sync = std::make_unique<ProxySync>(h.config, h.archive);
  h.device.set = SyncHarness::custom_set(5);
  h.device.direction = SyncDirection::kUpload;
  ASSERT_TRUE(h.run_sync());
  const auto v = h.real->current(SyncHarness::kStation).value().version;
  EXPECT_EQ(v.at, kWall);
  EXPECT_FALSE(v.simulated);
}

}  // namespace
}  // namespace rs4sim::proxy::testing
