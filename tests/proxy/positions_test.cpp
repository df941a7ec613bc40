// Every ERROR_NUMBER_FB the manual lists ([RS4 manual §6.4]) is reached by a failure
// injected at the step docs/proxy.md "Position map" assigns it to.
#include "proxy/positions.h"

#include "tests/proxy/sync_harness.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace rs4sim::proxy::testing {
namespace {

using rs4::protocol::SyncDirection;
using rs4::protocol::SyncReason;
using Op = FaultyArchive::Op;

enum class Scenario : std::uint8_t { kVerify, kUpload, kDownload, kExchange };

struct Case {
  std::uint16_t code;
  Scenario scenario;
  Step step;
  FailureKind kind;
  Op archive_fault = Op::kNone;
};

std::string name_of(const ::testing::TestParamInfo<Case>& info) {
  char text[16];
  std::snprintf(text, sizeof text, "Code%04X", static_cast<unsigned>(info.param.code));
  return text;
}

const Case kCases[] = {
    // write failures 02 04 08 10 11 21 24 26 27 29 32 33 40 45
    {0x0201, Scenario::kVerify, Step::kBegin, FailureKind::kWrite},
    {0x0401, Scenario::kVerify, Step::kIdentify1, FailureKind::kWrite},
    {0x0801, Scenario::kUpload, Step::kUpload1, FailureKind::kWrite},
    {0x1001, Scenario::kUpload, Step::kUpload2, FailureKind::kWrite},
    {0x1101, Scenario::kVerify, Step::kVerifyUpload1, FailureKind::kWrite},
    {0x2101, Scenario::kDownload, Step::kDownloadBegin, FailureKind::kWrite},
    {0x2401, Scenario::kDownload, Step::kDownloadChunk, FailureKind::kWrite},
    {0x2601, Scenario::kDownload, Step::kDownloadCommit, FailureKind::kWrite},
    {0x2701, Scenario::kDownload, Step::kReidentify1, FailureKind::kWrite},
    {0x2901, Scenario::kDownload, Step::kReidentify2, FailureKind::kWrite},
    {0x3201, Scenario::kVerify, Step::kVerifyIdentify1, FailureKind::kWrite},
    {0x3301, Scenario::kVerify, Step::kVerifyIdentify2, FailureKind::kWrite},
    {0x4001, Scenario::kVerify, Step::kEnd, FailureKind::kWrite},
    {0x4501, Scenario::kVerify, Step::kVerifyUpload2, FailureKind::kWrite},
    // read failures 03 05 06 07 12 22 23 28 30 31 34 41 50
    {0x0301, Scenario::kVerify, Step::kBegin, FailureKind::kRead},
    {0x0501, Scenario::kVerify, Step::kIdentify1, FailureKind::kRead},
    {0x0601, Scenario::kVerify, Step::kIdentify2, FailureKind::kRead},
    {0x0701, Scenario::kUpload, Step::kUpload1, FailureKind::kRead},
    {0x1201, Scenario::kUpload, Step::kUpload2, FailureKind::kRead},
    {0x2201, Scenario::kDownload, Step::kDownloadBegin, FailureKind::kRead},
    {0x2301, Scenario::kDownload, Step::kDownloadChunk, FailureKind::kRead},
    {0x2801, Scenario::kDownload, Step::kDownloadCommit, FailureKind::kRead},
    {0x3001, Scenario::kDownload, Step::kReidentify1, FailureKind::kRead},
    {0x3101, Scenario::kDownload, Step::kReidentify2, FailureKind::kRead},
    {0x3401, Scenario::kVerify, Step::kVerifyIdentify1, FailureKind::kRead},
    {0x4101, Scenario::kVerify, Step::kEnd, FailureKind::kRead},
    {0x5001, Scenario::kVerify, Step::kVerifyUpload1, FailureKind::kRead},
    // bad records 03 05 06 09 12 22 23 28 30 31 34 41
    {0x0302, Scenario::kVerify, Step::kBegin, FailureKind::kBadRecord},
    {0x0502, Scenario::kVerify, Step::kIdentify1, FailureKind::kBadRecord},
    {0x0602, Scenario::kVerify, Step::kIdentify2, FailureKind::kBadRecord},
    {0x0902, Scenario::kUpload, Step::kUpload1, FailureKind::kBadRecord},
    {0x1202, Scenario::kUpload, Step::kUpload2, FailureKind::kBadRecord},
    {0x2202, Scenario::kDownload, Step::kDownloadBegin, FailureKind::kBadRecord},
    {0x2302, Scenario::kDownload, Step::kDownloadChunk, FailureKind::kBadRecord},
    {0x2802, Scenario::kDownload, Step::kDownloadCommit, FailureKind::kBadRecord},
    {0x3002, Scenario::kDownload, Step::kReidentify1, FailureKind::kBadRecord},
    {0x3102, Scenario::kDownload, Step::kReidentify2, FailureKind::kBadRecord},
    {0x3402, Scenario::kVerify, Step::kVerifyIdentify2, FailureKind::kBadRecord},
    {0x4102, Scenario::kVerify, Step::kEnd, FailureKind::kBadRecord},
    // copies 01 25 (load → work) 13 42 (work → load)
    {0x0101, Scenario::kVerify, Step::kLoadCurrent, FailureKind::kCopy, Op::kCurrent},
    {0x1301, Scenario::kUpload, Step::kStoreUpload, FailureKind::kCopy, Op::kStore},
    {0x2501, Scenario::kDownload, Step::kLoadDownload, FailureKind::kCopy, Op::kGet},
    {0x4201, Scenario::kExchange, Step::kStoreSerial, FailureKind::kCopy, Op::kStore},
};

class PositionTest : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override {
    const auto& c = GetParam();
    const auto stored = SyncHarness::custom_set(3);
    switch (c.scenario) {
      case Scenario::kVerify:  // consistent: release at once, background verify
        h_.device.set = stored;
        h_.store(stored, "1001");
        break;
      case Scenario::kUpload:  // the PC adapter was removed: a new set on the device
        h_.store(stored, "1001");
        h_.device_changed_to(SyncHarness::custom_set(5), SyncReason::kPcAdapterRemoved);
        break;
      case Scenario::kDownload:  // the device fell back to factory settings
        h_.store(stored, "1001");
        h_.device.factory = true;
        h_.device.direction = SyncDirection::kDownload;
        break;
      case Scenario::kExchange:  // a new device on the address
        h_.store(stored, "999");
        h_.device.set = SyncHarness::custom_set(7);
        break;
    }
    h_.archive.fail = c.archive_fault;
    if (c.kind != FailureKind::kCopy) h_.inject = Injection{c.step, c.kind};
  }
  SyncHarness h_;
};

TEST_P(PositionTest, FailureGivesTheManualsErrorNumber) {
  const auto& c = GetParam();
  ASSERT_EQ(error_number_fb(c.step, c.kind), c.code);
  ASSERT_TRUE(h_.run_sync());
  const auto& out = h_.sync->outputs();
  EXPECT_EQ(out.error_number_fb, c.code);
  EXPECT_FALSE(out.fb_busy);
  EXPECT_FALSE(h_.device.sync_running);  // never left open on the device
  // ERROR_CODE_SFC: the S7 RET_VAL W#16#80xx, xx = Error_Code_1 (0x80B5, 0x80A0)
  // [docs/decisions.md#proxy-error-code-sfc].
  const auto sfc = c.kind == FailureKind::kWrite  ? std::uint16_t{0x8000 | kWriteRefusedCode1}
                   : c.kind == FailureKind::kRead ? std::uint16_t{0x8000 | kReadRefusedCode1}
                                                  : std::uint16_t{0};
  EXPECT_EQ(out.error_code_sfc, sfc);
  // Every failure once 98 was written is reported to the device and taken by it: the background
  // verify's and an unreadable answer to 99 success too, since the device takes a failure report
  // until the next sync ([RS4 manual §5.1.1] bit 2: an error of the parameter check sets
  // Proxy-Request again).
  const bool device_told = c.code != 0x0101 && c.code != 0x0201;
  if (device_told) {
    ASSERT_TRUE(h_.device.last_end.has_value());
    EXPECT_EQ(h_.device.last_end->outcome, rs4::protocol::ProxyOutcome::kFailed);
    EXPECT_TRUE(out.config_set_to_default);  // the device fell back to factory settings
  } else {
    EXPECT_TRUE(!h_.device.last_end ||
                h_.device.last_end->outcome == rs4::protocol::ProxyOutcome::kSucceeded);
  }
  // Stop on error: the next sync waits for the retry delay.
  h_.sync->set_input_byte(0x04);
  h_.sync->set_proxy_enable(true);
  EXPECT_FALSE(h_.sync->ready(h_.now));
  EXPECT_TRUE(h_.sync->ready(h_.now + h_.config.retry_delay));
}

INSTANTIATE_TEST_SUITE_P(ManualList, PositionTest, ::testing::ValuesIn(kCases), name_of);

// The map uses only the positions the manual lists for each kind, and all of them.
TEST(PositionMap, UsesExactlyTheManualsPositionsPerKind) {
  const std::set<int> write{0x02, 0x04, 0x08, 0x10, 0x11, 0x21, 0x24,
                            0x26, 0x27, 0x29, 0x32, 0x33, 0x40, 0x45};
  const std::set<int> read{0x03, 0x05, 0x06, 0x07, 0x12, 0x22, 0x23,
                           0x28, 0x30, 0x31, 0x34, 0x41, 0x50};
  const std::set<int> bad{0x03, 0x05, 0x06, 0x09, 0x12, 0x22, 0x23, 0x28, 0x30, 0x31, 0x34, 0x41};
  const std::set<int> copy{0x01, 0x13, 0x25, 0x42};
  std::set<int> w, r, b, c;
  for (std::size_t i = 0; i < kStepCount; ++i) {
    const auto p = positions(static_cast<Step>(i));
    if (p.write != 0) w.insert(p.write);
    if (p.read != 0) r.insert(p.read);
    if (p.bad != 0) b.insert(p.bad);
    if (p.copy != 0) c.insert(p.copy);
  }
  EXPECT_EQ(w, write);
  EXPECT_EQ(r, read);
  EXPECT_EQ(b, bad);
  EXPECT_EQ(c, copy);
  EXPECT_EQ(std::size(kCases), write.size() + read.size() + bad.size() + copy.size());
}

}  // namespace
}  // namespace rs4sim::proxy::testing
