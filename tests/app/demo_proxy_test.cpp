// The demo's parameter proxy (app/demos/demo_proxy.h): ProxyScheduler + ProxyDriver on the
// segment's master cycles, as `rs4sim master` hosts them. On the manual clock: the RS4 asks
// (Proxy-Request, input bit 2 [RS4 manual §5.1.1]) and the proxy answers on its own, with no
// call from the story; wait_sync() waits for a sync, bounded on both sides.
#include "app/demos/demo_proxy.h"
#include "app/runtime/master_proxy.h"
#include "dp/master/master_error.h"

#include "rs4/adapter/cyclic_bytes.h"
#include "storage/sqlite_archive.h"

#include <gtest/gtest.h>

namespace rs4sim::app {
namespace {

using namespace std::chrono_literals;
using rs4::adapter::kInputOssd;
using rs4::adapter::kInputProxyRequest;

struct DemoProxyTest : ::testing::Test {
  static rs4::device::Rs4SegmentConfig config() {
    rs4::device::Rs4SegmentConfig c;
    c.device.boot_time = 3s;
    c.output_byte = rs4::adapter::kOutputProxyEnable | 0x01;  // Proxy-Enable, field pair 1
    return c;
  }
  rs4::device::Rs4Segment seg{config()};
  std::unique_ptr<storage::SqliteArchive> archive = [] {
    auto a = storage::SqliteArchive::open(":memory:");
    EXPECT_TRUE(a) << a.error().message;
    return std::move(a).value();
  }();
  DemoProxy proxy{seg, *archive};
  RunUntil run = [this](const std::function<bool()>& done, dp::Duration limit) {
    return seg.run_until(done, limit);
  };

  bool proxy_request() const { return (seg.input_byte() & kInputProxyRequest) != 0; }
};

TEST_F(DemoProxyTest, AnswersTheProxyRequestOnItsOwn) {
  seg.power_on();
  ASSERT_TRUE(seg.run_until([&] { return proxy_request(); }, 4s));
  // Nothing but time: the driver sees bit 2 on a cycle and runs the whole sync (≈ 200 ms).
  seg.run_for(2s);
  EXPECT_FALSE(proxy_request());
  // First commissioning, factory settings, nothing archived ([RS4 manual §7.1] scenario 1).
  EXPECT_TRUE(proxy.outputs().config_set_to_default);
  EXPECT_EQ(proxy.outputs().error_number_fb, 0);
  EXPECT_EQ(proxy.station().bus, "demo");
  EXPECT_EQ(proxy.station().address, seg.rs4_address());
  // IDENTIFY, the check of the set and the release: the records went out through the master
  // (the demo's figure for a first commissioning).
  EXPECT_EQ(proxy.records(), 10U);
  // Nothing to archive: the RS4 keeps its factory set and the archive stays empty.
  EXPECT_FALSE(archive->current(proxy.station()));
}

TEST_F(DemoProxyTest, WaitSyncReturnsWhenTheSyncEndsAndReportsEveryRecord) {
  seg.power_on();
  ASSERT_TRUE(seg.run_until([&] { return proxy_request(); }, 4s));
  std::size_t reports = 0;
  const auto at = seg.now();
  ASSERT_TRUE(proxy.wait_sync(run, 120s, [&](const proxy::SyncProgress&) { ++reports; }));
  // It returned at the sync's end, not at its limit, and after the last record.
  EXPECT_LT(seg.now() - at, 1s);
  EXPECT_GT(seg.now() - at, 100ms);  // ten records of two 10 ms cycles each, at least
  EXPECT_FALSE(proxy_request());
  EXPECT_EQ(reports, proxy.records());
  EXPECT_EQ(proxy.records(), 10U);
}

TEST_F(DemoProxyTest, WaitSyncWithoutARequestRunsToItsLimit) {
  seg.power_on();
  ASSERT_TRUE(seg.run_until([&] { return proxy_request(); }, 4s));
  ASSERT_TRUE(proxy.wait_sync(run, 120s, {}));
  const auto at = seg.now();
  EXPECT_FALSE(proxy.wait_sync(run, 500ms, {}));
  EXPECT_GE(seg.now() - at, 500ms);
  EXPECT_LE(seg.now() - at, 501ms);
}

TEST_F(DemoProxyTest, ProxyEnableOffLeavesTheRequestUnanswered) {
  seg.set_output_byte(0x01);  // field pair 1, Proxy-Enable off ([RS4 manual §5.1.2] bit 6)
  seg.power_on();
  ASSERT_TRUE(seg.run_until([&] { return seg.in_data_exchange(); }, 5s));
  // The FB gets the PLC's Proxy-Enable 0: it answers no request and sends no record.
  seg.run_for(5s);
  EXPECT_EQ(proxy.records(), 0U);
  EXPECT_FALSE(proxy.outputs().config_set_to_default);
}

// ERROR_CODE_SFC as the S7 RET_VAL of RD_REC/WR_REC ([RS4 manual §6.4]: decoded with the SIMATIC
// reference): W#16#80 + Error_Code_1 of a negative response, W#16#80C5 without a response
// [docs/decisions.md#proxy-error-code-sfc].
TEST(ToRecordResult, SfcIsTheS7ReturnValue) {
  dp::master::Dpv1Result ok;
  ok.data = {0x31, 0x04, 0xFF, 0xFF};
  const auto good = to_record_result(ok);
  EXPECT_TRUE(good.ok);
  EXPECT_EQ(good.sfc, 0);
  dp::master::Dpv1Result refused;
  refused.error = dp::master::MasterError::kDpv1Negative;
  refused.negative = dp::pdu::Dpv1Error{dp::pdu::Dpv1Function::kWrite, 0x80,
                                        dp::pdu::ErrorCode1::kStateConflict, 0x07};
  const auto neg = to_record_result(refused);
  EXPECT_FALSE(neg.ok);
  EXPECT_EQ(neg.sfc, 0x80B5);
  dp::master::Dpv1Result lost;
  lost.error = dp::master::MasterError::kDpv1Timeout;
  EXPECT_EQ(to_record_result(lost).sfc, 0x80C5);
  lost.error = dp::master::MasterError::kAborted;
  EXPECT_EQ(to_record_result(lost).sfc, 0x80C5);
}

}  // namespace
}  // namespace rs4sim::app
