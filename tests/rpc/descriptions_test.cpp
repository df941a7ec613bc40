// Each device's description (gridscan/, metron/, polaris/ description.h) agrees with the
// API's Counters message and fault enum (rpc/proto/rs4sim/v1/devices.proto, read through the
// protobuf descriptor, not through our code) and with the end-of-run summary, whose expected
// lines are written out here by hand from each counters.h.
#include "gridscan/description.h"
#include "metron/description.h"
#include "polaris/description.h"
#include "rs4sim/v1/devices.pb.h"
#include "tests/description_agreement.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace rs4sim::gridscan {
namespace {

TEST(GridScanDescription, AgreesWithGridScanCountersAndGridScanFault) {
  // gridscan/counters.h: 15 counters and dropped(), their sum of the nine reasons. LATE_ANSWER,
  // LATE's deprecated alias, is no fault of its own.
  EXPECT_EQ(description().counters.size(), 16U);
  testing::expect_description_agrees(description(), *v1::GridScanCounters::descriptor(),
                                     *v1::GridScanFault_descriptor(), "GRID_SCAN_FAULT_");
  EXPECT_EQ(description().kind, stream::DeviceKind::kGridScan);
}

TEST(GridScanDescription, TheSummaryShowsEveryCounterAndTheDroppedSum) {
  // In the order of gridscan/counters.h; dropped = 5 + 6 + ... + 13 = 81.
  const Counters k{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
  EXPECT_EQ(stream::counters_summary(description(), k),
            "frames 1, answered 2, communication tests 3, streamed 4, dropped 81, truncated 5, "
            "oversized 6, sync 7, CRC 8, SeqCnt 9, ID 10, direction 11, busy 12, not ready 13, "
            "restarts 14, mode fallbacks 15");
}

}  // namespace
}  // namespace rs4sim::gridscan

namespace rs4sim::metron {
namespace {

TEST(MetronDescription, AgreesWithMetronCountersAndMetronFault) {
  // metron/counters.h holds 18 counters (E1..E5 one array): all of them are described.
  EXPECT_EQ(description().counters.size(), 18U);
  testing::expect_description_agrees(description(), *v1::MetronCounters::descriptor(),
                                     *v1::MetronFault_descriptor(), "METRON_FAULT_");
}

TEST(MetronDescription, TheSummaryShowsEveryCounter) {
  // In the order of metron/counters.h.
  const Counters k{1,  2,  3, {41, 42, 43, 44, 45}, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15,
                   16, 17, 18};
  EXPECT_EQ(stream::counters_summary(description(), k),
            "messages 1, executed 2, frames sent 3, E1..E5 41/42/43/44/45, parity rejected 5, "
            "not for us 6, broadcasts ignored 7, noise bytes 8, truncated 9, too long 10, "
            "resync bytes 11, ignored in reset 12, resets 13, reports 14, reports dropped 15, "
            "report requests 16, other bytes 17, suppressed 18");
}

TEST(MetronDescription, KindAndNodeRange) {
  EXPECT_EQ(description().kind, stream::DeviceKind::kMetron);
  EXPECT_EQ(description().link, stream::LinkKind::kMetron);
  // The node is 0..254, 255 the broadcast address [METRON manual "With node"].
  const auto& options = description().options;
  const auto node = std::find_if(options.begin(), options.end(),
                                 [](const stream::OptionInfo& o) { return o.flag == "--node"; });
  ASSERT_NE(node, options.end());
  EXPECT_EQ(node->min, 0);
  EXPECT_EQ(node->max, 254);
}

}  // namespace
}  // namespace rs4sim::metron

namespace rs4sim::polaris {
namespace {

TEST(PolarisDescription, AgreesWithPolarisCountersAndPolarisFault) {
  // polaris/counters.h holds 16. NO_ANSWER, SILENT's deprecated alias, is no fault of its own.
  EXPECT_EQ(description().counters.size(), 16U);
  testing::expect_description_agrees(description(), *v1::PolarisCounters::descriptor(),
                                     *v1::PolarisFault_descriptor(), "POLARIS_FAULT_");
}

TEST(PolarisDescription, TheSummaryShowsEveryCounter) {
  // In the order of polaris/counters.h.
  const Counters k{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
  EXPECT_EQ(stream::counters_summary(description(), k),
            "requests 1, CRC errors 2, too short 3, oversized 4, broadcasts 5, other addresses 6, "
            "bad function 7, bad request 8, bad start 9, busy 10, configuration writes 11, "
            "refused writes 12, answers ignored 13, exceptions sent 14, frames sent 15, "
            "suppressed 16");
}

TEST(PolarisDescription, AModbusAddressIs1To247) {
  // [Modbus serial line V1.02 §2.2]
  const auto& o = description().options.front();
  EXPECT_EQ(o.flag, "--address");
  EXPECT_EQ(o.min, 1);
  EXPECT_EQ(o.max, 247);
  EXPECT_EQ(description().link, stream::LinkKind::kModbusRtu);
}

}  // namespace
}  // namespace rs4sim::polaris
