// Fault injection: the faults a controller must catch (metron/faults.h).
#include "tests/metron/metron_line.h"

#include <gtest/gtest.h>

namespace rs4sim::metron::testing {
namespace {

using namespace std::chrono_literals;

const Bytes kRequest{0x02, 0x01, 0x0C, 0xF3};

// Changes the device's faults as a client does: a copy, changed, set back (the setter wakes).
template <typename Change>
void set_fault(Rig& rig, Change change) {
  Faults f = rig.device().faults();
  change(f);
  rig.device().set_faults(f);
}

TEST(MetronFaults, Silent) {
  Rig rig(slave_options());
  set_fault(rig, [](Faults& f) { f.transmit.silent = true; });
  EXPECT_TRUE(rig.silent(kRequest));
  EXPECT_EQ(rig.device().counters().suppressed, 1U);
  EXPECT_EQ(rig.device().counters().executed, 1U);  // the command still ran
}

TEST(MetronFaults, LateAnswer) {
  Rig rig(slave_options());
  set_fault(rig, [](Faults& f) { f.transmit.late = 50ms; });
  const auto t0 = rig.now();
  const auto s = rig.exchange(kRequest);
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(s[0].start, t0 + 62'291'667ns);
}

TEST(MetronFaults, BadChecksum) {
  Rig rig(slave_options());
  set_fault(rig, [](Faults& f) { f.bad_checksum = true; });
  const auto s = rig.exchange(kRequest);
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(s[0].bytes, (Bytes{0x02, 0x03, 0x0C, 0x01, 0x01, 0x0E /* ~0xF1 */}));
}

TEST(MetronFaults, WrongNode) {
  Rig rig(node_options(5));
  set_fault(rig, [](Faults& f) { f.wrong_node = true; });
  const auto s = rig.exchange({0x02, 0x05, 0x01, 0x0C, 0xF3});
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(s[0].bytes[1], 0x06);
}

TEST(MetronFaults, Truncated) {
  Rig rig(slave_options());
  set_fault(rig, [](Faults& f) { f.truncate = true; });
  const auto s = rig.exchange(kRequest);
  ASSERT_EQ(s.size(), 1U);
  EXPECT_EQ(s[0].bytes, (Bytes{0x02, 0x03, 0x0C, 0x01, 0x01}));
}

TEST(MetronFaults, StandardReportBadChecksum) {
  Options o;
  o.line_mode = LineMode::kStandard;
  o.checksum = true;
  Rig rig(o);
  set_fault(rig, [](Faults& f) { f.bad_checksum = true; });
  rig.run_for(14ms);  // the report at 10 ms, 6 characters (3.44 ms) on the wire at 19200 8E1
  const auto s = rig.take();
  ASSERT_EQ(s.size(), 1U);
  // STX, 0, 0, 0 (free curtain), checksum ~0 = 0xFF inverted -> 0x00, ETX
  EXPECT_EQ(s[0].bytes, (Bytes{0x02, 0x00, 0x00, 0x00, 0x00, 0x03}));
}

}  // namespace
}  // namespace rs4sim::metron::testing
