// Slave line mode with node: the address filter, the node number in every reply and the
// broadcast rules [METRON manual "With node"]. Node 5 throughout.
#include "tests/metron/metron_line.h"

#include <gtest/gtest.h>

namespace rs4sim::metron::testing {
namespace {

TEST(MetronNode, OwnAddressIsAnsweredWithTheNodeNumber) {
  Rig rig(node_options(5));
  const auto s = rig.exchange({0x02,    // frame start
                               0x05,    // address: node 5
                               0x01,    // length
                               0x0C,    // #12 Request OSSD status
                               0xF3});  // checksum (address and length not covered)
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(s[0].bytes, (Bytes{0x02, 0x05 /* responding node */, 0x03, 0x0C, 0x01, 0x01, 0xF1}));
}

TEST(MetronNode, ReplyTimingCountsTheAddressByte) {
  using namespace std::chrono_literals;
  Rig rig(node_options(5));
  const auto t0 = rig.now();
  rig.send({0x02, 0x05, 0x01, 0x0C, 0xF3});
  rig.run_to(t0 + 20ms);
  const auto s = rig.take();
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(s[0].start, t0 + 10ms + 2'864'584ns);  // 55 bits at 19200 + t_response/2
}

TEST(MetronNode, OtherAddressIsIgnored) {
  Rig rig(node_options(5));
  EXPECT_TRUE(rig.silent({0x02, 0x06, 0x01, 0x03, 0xFC}));
  EXPECT_EQ(rig.device().slave_state().ossd, OssdFunction::kEnabled);  // not executed
  EXPECT_TRUE(rig.silent({0x02, 0x06, 0x01, 0x03, 0x00}));   // not even E1
  EXPECT_EQ(rig.device().counters().not_for_us, 2U);
}

TEST(MetronNode, BroadcastExecutesCommandsOneToSevenSilently) {
  Rig rig(node_options(5));
  EXPECT_TRUE(rig.silent({0x02, 0xFF /* broadcast */, 0x01, 0x03, 0xFC}));
  EXPECT_EQ(rig.device().slave_state().ossd, OssdFunction::kDisabled);
  EXPECT_TRUE(rig.silent({0x02, 0xFF, 0x01, 0x02, 0xFD}));
  EXPECT_TRUE(rig.silent({0x02, 0xFF, 0x02, 0x07, 0x01, 0xF7}));
  EXPECT_TRUE(rig.device().slave_state().measuring.has_value());
  EXPECT_EQ(rig.device().counters().executed, 3U);
}

TEST(MetronNode, BroadcastStopMeasurementIsIgnored) {
  Rig rig(node_options(5));
  rig.exchange({0x02, 0x05, 0x02, 0x07, 0x01, 0xF7});
  EXPECT_TRUE(rig.silent({0x02, 0xFF, 0x01, 0x08, 0xF7}));
  EXPECT_TRUE(rig.device().slave_state().measuring.has_value());  // the measurement goes on
}

TEST(MetronNode, BroadcastRequestsAreDroppedWithoutReply) {
  Rig rig(node_options(5));
  for (const Bytes& r :
       {Bytes{0x02, 0xFF, 0x02, 0x09, 0x00, 0xF6}, Bytes{0x02, 0xFF, 0x01, 0x0B, 0xF4},
        Bytes{0x02, 0xFF, 0x01, 0x0C, 0xF3}, Bytes{0x02, 0xFF, 0x01, 0x0D, 0xF2}})
    EXPECT_TRUE(rig.silent(r));
  EXPECT_EQ(rig.device().counters().broadcast_ignored, 4U);
}

TEST(MetronNode, BroadcastResetAndBroadcastErrorsGetNoReply) {
  Rig rig(node_options(5));
  EXPECT_TRUE(rig.silent({0x02, 0xFF, 0x01, 0x01, 0x00 /* bad checksum */}));
  EXPECT_EQ(rig.device().counters().resets, 0U);
  EXPECT_TRUE(rig.silent({0x02, 0xFF, 0x01, 0x06, 0xF9 /* E3 */}));
  EXPECT_TRUE(rig.silent({0x02, 0xFF, 0x01, 0x01, 0xFE}));  // reset, executed
  EXPECT_EQ(rig.device().counters().resets, 1U);
}

TEST(MetronNode, ResetToOwnNodeIsNotAnswered) {
  Rig rig(node_options(5));
  EXPECT_TRUE(rig.silent({0x02, 0x05, 0x01, 0x01, 0xFE}));
  EXPECT_EQ(rig.device().counters().resets, 1U);
}

TEST(MetronNode, ErrorsToOwnNodeCarryTheNode) {
  Rig rig(node_options(5));
  const auto s = rig.exchange({0x02, 0x05, 0x01, 0x0C, 0x00});
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(s[0].bytes, (Bytes{0x02, 0x05, 0x01, 0xE1, 0x1E}));
}

}  // namespace
}  // namespace rs4sim::metron::testing
