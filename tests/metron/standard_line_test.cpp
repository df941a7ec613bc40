// Standard line mode's reporting modes on the manual clock [METRON manual "Continuous
// reporting" .. "Input-related reporting"]. Report: first, last, count in binary without
// separator: STX v v v ETX (EXTENSION framing).
#include "tests/metron/metron_line.h"

#include <gtest/gtest.h>

namespace rs4sim::metron::testing {
namespace {

using namespace std::chrono_literals;

Options standard(ReportingMode m) {
  Options o;
  o.line_mode = LineMode::kStandard;
  o.reporting_mode = m;
  return o;
}

std::vector<stream::Duration> times(const std::vector<LineFrame>& s, stream::TimePoint t0) {
  std::vector<stream::Duration> out;
  for (const auto& x : s) out.push_back(x.start - t0);
  return out;
}

TEST(MetronStandard, ContinuousSendsEveryScanCycle) {
  Rig rig(standard(ReportingMode::kContinuous));
  const auto t0 = rig.now();
  rig.run_for(33ms);  // the 30 ms report's 5 characters arrive 2.86 ms later (19200 8E1)
  const auto s = rig.take();
  EXPECT_EQ(times(s, t0), (std::vector<stream::Duration>{10ms, 20ms, 30ms}));
  EXPECT_EQ(s[0].bytes, (Bytes{0x02, 0x00, 0x00, 0x00, 0x03}));
}

TEST(MetronStandard, ContinuousDropsWhileThePreviousIsOnTheLine) {
  auto o = standard(ReportingMode::kContinuous);
  o.baud = 1200;
  o.parity = stream::Parity::kNone;
  o.format = Format::kDecimal;
  o.separator = true;
  o.checksum = true;  // 4n + 1 + 1 = 14 bytes: 140 bits / 1200 + 1 ms = 117.67 ms
  Rig rig(o);
  const auto t0 = rig.now();
  rig.run_for(300ms);
  EXPECT_EQ(rig.device().counters().reports_dropped, 27U);
  rig.run_to(t0 + 367ms);  // the 250 ms report's 140 bits arrive 116.67 ms later
  EXPECT_EQ(times(rig.take(), t0), (std::vector<stream::Duration>{10ms, 130ms, 250ms}));
}

TEST(MetronStandard, Periodical) {
  auto o = standard(ReportingMode::kPeriodical);
  o.period = 50ms;
  Rig rig(o);
  const auto t0 = rig.now();
  rig.run_for(203ms);  // the 200 ms report arrives 2.86 ms later
  EXPECT_EQ(times(rig.take(), t0), (std::vector<stream::Duration>{50ms, 100ms, 150ms, 200ms}));
}

TEST(MetronStandard, OnRequestAnswersAtTheNextCycle) {
  Rig rig(standard(ReportingMode::kOnRequest));
  const auto t0 = rig.now();
  rig.run_for(3ms);
  rig.send({0x3F});  // '?' (EXTENSION request character)
  rig.run_for(50ms);
  EXPECT_EQ(times(rig.take(), t0), (std::vector<stream::Duration>{10ms}));
  EXPECT_EQ(rig.device().counters().report_requests, 1U);
}

TEST(MetronStandard, StatusChangeSendsOnlyWhenBeamsChange) {
  Rig rig(standard(ReportingMode::kStatusChange));
  const auto t0 = rig.now();
  rig.run_for(25ms);
  rig.device().set_beam(7, true);
  rig.run_for(25ms);
  const auto s = rig.take();
  EXPECT_EQ(times(s, t0), (std::vector<stream::Duration>{10ms, 30ms}));
  EXPECT_EQ(s[1].bytes, (Bytes{0x02, 0x07, 0x07, 0x01, 0x03}));
}

TEST(MetronStandard, InputEnableLine) {
  auto o = standard(ReportingMode::kInputRelated);
  o.input_type = InputType::kEnableLine;
  Rig rig(o);
  const auto t0 = rig.now();
  rig.run_for(25ms);
  rig.device().set_input(true);
  rig.run_for(20ms);
  EXPECT_EQ(times(rig.take(), t0), (std::vector<stream::Duration>{30ms, 40ms}));
}

TEST(MetronStandard, InputNoFunctionIsContinuous) {
  auto o = standard(ReportingMode::kInputRelated);
  Rig rig(o);
  rig.run_for(23ms);  // reports at 10 and 20 ms, the second arrives 2.86 ms later
  EXPECT_EQ(rig.take().size(), 2U);
}

TEST(MetronStandard, InputStartStopSendsTheMaximumThreeTimes) {
  auto o = standard(ReportingMode::kInputRelated);
  o.input_type = InputType::kStartStopLine;
  o.report = {Measurement::kInterruptedCount};
  Rig rig(o);
  const auto t0 = rig.now();
  rig.run_for(5ms);
  rig.device().set_input(true);  // leading edge: monitoring starts
  const std::uint16_t five[] = {1, 2, 3, 4, 5};
  const std::uint16_t eight[] = {1, 2, 3, 4, 5, 6, 7, 8};
  const std::uint16_t two[] = {1, 2};
  rig.device().set_interrupted(five);
  rig.run_for(10ms);
  rig.device().set_interrupted(eight);
  rig.run_for(10ms);
  rig.device().set_interrupted(two);
  rig.run_for(10ms);
  EXPECT_TRUE(rig.quiet());  // nothing while monitoring
  rig.device().set_input(false);    // trailing edge at 35 ms
  rig.run_for(60ms);
  const auto s = rig.take();
  EXPECT_EQ(times(s, t0), (std::vector<stream::Duration>{40ms, 50ms, 60ms}));
  for (const auto& x : s) EXPECT_EQ(x.bytes, (Bytes{0x02, 0x08 /* maximum */, 0x03}));
}

TEST(MetronStandard, InputStandbyRepeatsTheLastMessage) {
  auto o = standard(ReportingMode::kInputRelated);
  o.input_type = InputType::kLineStandby;
  Rig rig(o);
  rig.device().set_beam(4, true);
  rig.run_for(15ms);
  rig.device().set_input(true);  // frozen from here
  rig.device().set_beam(9, true);
  rig.run_for(20ms);
  rig.device().set_input(false);
  rig.run_for(10ms);
  const auto s = rig.take();
  ASSERT_EQ(s.size(), 4U);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(s[i].bytes, (Bytes{0x02, 0x04, 0x04, 0x01, 0x03}));
  EXPECT_EQ(s[3].bytes, (Bytes{0x02, 0x04, 0x09, 0x02, 0x03}));
}

TEST(MetronStandard, LineSettingsAreConfigured) {
  EXPECT_EQ(line_asked_for_9600_8n1(standard(ReportingMode::kContinuous)),
            (stream::LineSettings{9600, 8, stream::Parity::kNone, 1}));
}

}  // namespace
}  // namespace rs4sim::metron::testing
