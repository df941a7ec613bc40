// Options::validate() names what is wrong; the wire table's own checks; the scene's
// measurements and beam packing.
#include "metron/options.h"

#include "metron/mode_spec.h"
#include "metron/scene.h"

#include <gtest/gtest.h>

namespace rs4sim::metron {
namespace {

using namespace std::chrono_literals;

TEST(MetronOptions, DefaultsAreValid) { EXPECT_EQ(Options{}.validate(), ""); }

TEST(MetronOptions, Messages) {
  Options o;
  o.beams = 0;
  EXPECT_EQ(o.validate(), "beams must be 1..255");
  o = {};
  o.node_enabled = true;
  o.node = 255;
  EXPECT_EQ(o.validate(), "node must be 0..254 (255 is broadcast)");
  o = {};
  o.line_mode = LineMode::kStandard;
  o.reporting_mode = ReportingMode::kPeriodical;
  o.period = 60ms;
  EXPECT_EQ(o.validate(), "period must be one of 50, 100, 250, 500, 750 ms, 1, 1.25, 1.5, 2, 3 s");
  o.period = 1250ms;
  EXPECT_EQ(o.validate(), "");
  o.reporting_mode = ReportingMode::kInputRelated;
  o.input_type = InputType::kStartStopAll;
  EXPECT_EQ(o.validate(), "input type start-stop needs exactly one report measurement");
  o = {};
  o.wire.errors[2] = 0x03;
  EXPECT_EQ(o.validate(), "wire table: error answer code 0x03 is also a command code");
  o = {};
  o.wire.commands[1] = 0x01;
  EXPECT_EQ(o.validate(), "wire table: two commands share a code");
}

TEST(MetronOptions, Names) {
  EXPECT_EQ(parse_reporting_mode("status-change"), ReportingMode::kStatusChange);
  EXPECT_EQ(parse_input_type("all-standby"), InputType::kAllStandby);
  EXPECT_EQ(parse_format("hex"), Format::kHex);
  EXPECT_EQ(parse_line_mode("slave"), LineMode::kSlave);
  EXPECT_FALSE(parse_format("octal"));
  EXPECT_EQ(to_string(InputType::kStartStopLine), "start-stop-line");
  EXPECT_EQ(parse_measurement("run"), Measurement::kLongestRun);
}

TEST(MetronScene, Measurements) {
  Scene s(24);
  for (int b : {3, 4, 5, 10, 11}) s.set_interrupted(static_cast<std::uint16_t>(b), true);
  EXPECT_EQ(s.measure(Measurement::kFirstInterrupted), 3);
  EXPECT_EQ(s.measure(Measurement::kLastInterrupted), 11);
  EXPECT_EQ(s.measure(Measurement::kInterruptedCount), 5);
  EXPECT_EQ(s.measure(Measurement::kFreeCount), 19);
  EXPECT_EQ(s.measure(Measurement::kCentralInterrupted), 7);
  EXPECT_EQ(s.measure(Measurement::kLongestRun), 3);
  s.set_interrupted(0, true);   // no beam 0
  s.set_interrupted(25, true);  // no beam 25
  EXPECT_EQ(s.measure(Measurement::kInterruptedCount), 5);
}

TEST(MetronScene, PackingBitOrder) {
  Scene s(10);
  s.set_interrupted(1, true);
  s.set_interrupted(10, true);
  EXPECT_EQ(s.packed(true), (std::vector<std::uint8_t>{0x01, 0x02}));
  EXPECT_EQ(s.packed(false), (std::vector<std::uint8_t>{0x80, 0x40}));
}

}  // namespace
}  // namespace rs4sim::metron

namespace rs4sim::metron {
namespace {

TEST(MetronModeSpec, Slave) {
  Options o;
  o.line_mode = LineMode::kStandard;
  EXPECT_EQ(apply_mode_spec("slave", o), "");
  EXPECT_EQ(o.line_mode, LineMode::kSlave);
  EXPECT_EQ(apply_mode_spec("slave,hex", o),
            "slave mode takes only input=<type>, scan-cycle=<ms> and t-response=<ms> (19200 8E1 "
            "binary, fixed)");
  EXPECT_EQ(apply_mode_spec("slave,input=enable-line", o), "");
  EXPECT_EQ(o.line_mode, LineMode::kSlave);
  EXPECT_EQ(o.input_type, InputType::kEnableLine);
  EXPECT_EQ(apply_mode_spec("slave,input=sometimes", o), "unknown input type 'sometimes'");
}

TEST(MetronModeSpec, StandardWithOptions) {
  Options o;
  EXPECT_EQ(apply_mode_spec("periodical,hex,separator,checksum,period=250,report=count+run", o),
            "");
  EXPECT_EQ(o.line_mode, LineMode::kStandard);
  EXPECT_EQ(o.reporting_mode, ReportingMode::kPeriodical);
  EXPECT_EQ(o.format, Format::kHex);
  EXPECT_TRUE(o.separator);
  EXPECT_TRUE(o.checksum);
  EXPECT_EQ(o.period, std::chrono::milliseconds(250));
  EXPECT_EQ(o.report,
            (std::vector<Measurement>{Measurement::kInterruptedCount, Measurement::kLongestRun}));
  EXPECT_EQ(o.validate(), "");
  EXPECT_EQ(apply_mode_spec("input-related,input=line-standby", o), "");
  EXPECT_EQ(o.input_type, InputType::kLineStandby);
}

// The scan cycle and Equation 3's t_response from the user [METRON manual "Slave line mode"],
// in both line modes; validate() keeps its ranges (both sides).
TEST(MetronModeSpec, TimingWords) {
  Options o;
  EXPECT_EQ(apply_mode_spec("slave,scan-cycle=15,t-response=40", o), "");
  EXPECT_EQ(o.scan_cycle, std::chrono::milliseconds(15));
  EXPECT_EQ(o.t_response, std::chrono::milliseconds(40));
  EXPECT_EQ(apply_mode_spec("continuous,hex,scan-cycle=1000,t-response=2000", o), "");
  EXPECT_EQ(o.validate(), "");
  EXPECT_EQ(apply_mode_spec("slave,scan-cycle=1001", o), "");
  EXPECT_EQ(o.validate(), "scan cycle must be 1..1000 ms");
  EXPECT_EQ(apply_mode_spec("slave,scan-cycle=1,t-response=2001", o), "");
  EXPECT_EQ(o.validate(), "t_response must be 1..2000 ms");
  EXPECT_EQ(apply_mode_spec("slave,scan-cycle=0,t-response=1", o), "");
  EXPECT_EQ(o.validate(), "scan cycle must be 1..1000 ms");
  EXPECT_EQ(apply_mode_spec("slave,t-response=fast", o),
            "t-response= takes milliseconds, e.g. t-response=20");
  EXPECT_EQ(apply_mode_spec("slave,scan-cycle=", o),
            "scan-cycle= takes milliseconds, e.g. scan-cycle=10");
}

TEST(MetronModeSpec, Errors) {
  Options o;
  EXPECT_EQ(apply_mode_spec("sometimes", o),
            "mode must be slave, continuous, periodical, on-request, status-change or "
            "input-related, not 'sometimes'");
  EXPECT_EQ(apply_mode_spec("continuous,octal", o), "unknown mode option 'octal'");
  EXPECT_EQ(apply_mode_spec("continuous,period=x", o),
            "period= takes milliseconds, e.g. period=250");
  EXPECT_EQ(apply_mode_spec("continuous,report=first+tallest", o),
            "unknown measurement 'tallest' in report=");
  EXPECT_EQ(apply_mode_spec("continuous,input=maybe", o), "unknown input type 'maybe'");
}

}  // namespace
}  // namespace rs4sim::metron
