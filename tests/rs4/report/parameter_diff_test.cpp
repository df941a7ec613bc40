// Field-level diff of two sets with answers computed by hand.
#include "rs4/report/parameter_diff.h"

#include <gtest/gtest.h>

namespace rs4sim::rs4::report {
namespace {

using scanner::factory_default;

TEST(ParameterDiff, IdenticalSets) {
  const ParameterDiff d = diff(factory_default(), factory_default());
  EXPECT_TRUE(d.empty());
  EXPECT_EQ(render_text(d), "no differences\n");
  EXPECT_EQ(
      render_json(d),
      R"({"identical":true,"identity":[],"options":[],"passwords_changed":[],"contours":[]})");
}

TEST(ParameterDiff, RaisedProtectiveSegmentsAreOneRange) {
  // Factory pair 2 protective is 1500 mm; segments 100..140 raised by 350 mm.
  auto changed = factory_default();
  for (std::size_t n = 100; n <= 140; ++n) changed.pairs[1].protective_mm[n] = 1850;
  const ParameterDiff d = diff(factory_default(), changed);
  ASSERT_EQ(d.contours.size(), 1U);
  EXPECT_EQ(d.contours[0], (ContourChange{2, ContourKind::kProtective, {{100, 140, 350}}}));
  EXPECT_TRUE(d.options.empty());
  EXPECT_TRUE(d.identity.empty());
  EXPECT_EQ(render_text(d), "pair 2 protective: segments 100-140 changed, max +350 mm\n");
  EXPECT_EQ(render_json(d),
            R"({"identical":false,"identity":[],"options":[],"passwords_changed":[],)"
            R"("contours":[{"pair":2,"contour":"protective",)"
            R"("ranges":[{"first":100,"last":140,"max_change_mm":350}]}]})");
}

TEST(ParameterDiff, RangesSplitAtUnchangedSegmentsAndKeepTheSign) {
  // Pair 4 warning is 3500 mm. Segments 10, 11, 12: +5, −30, +30 (tie: the first, −30);
  // 13 unchanged; 20: −1000 alone; 528 (the last): +1.
  auto changed = factory_default();
  auto& w = changed.pairs[3].warning_mm;
  w[10] = 3505;
  w[11] = 3470;
  w[12] = 3530;
  w[20] = 2500;
  w[528] = 3501;
  const ParameterDiff d = diff(factory_default(), changed);
  ASSERT_EQ(d.contours.size(), 1U);
  EXPECT_EQ(d.contours[0].pair, 4);
  EXPECT_EQ(d.contours[0].contour, ContourKind::kWarning);
  EXPECT_EQ(d.contours[0].ranges,
            (std::vector<SegmentRange>{{10, 12, -30}, {20, 20, -1000}, {528, 528, 1}}));
  EXPECT_EQ(render_text(d),
            "pair 4 warning: segments 10-12 changed, max -30 mm\n"
            "pair 4 warning: segment 20 changed, -1000 mm\n"
            "pair 4 warning: segment 528 changed, +1 mm\n");
}

TEST(ParameterDiff, OptionsIdentityAndPasswords) {
  auto changed = factory_default();
  changed.identity.serial_number = 1234;
  changed.response_steps = 1;  // 80 → 120 ms
  changed.restart_mode = scanner::RestartMode::kStartInterlock;
  changed.start_pair = 3;
  changed.permitted[0] = 0x03;  // from pair 1: only 1 and 2
  changed.warning_output = 0x03;
  changed.measurement.stop = 400;
  changed.passwords[1] = {'H', 'U', 'N', 'T', 'E', 'R', '2', 0xFF};
  const ParameterDiff d = diff(factory_default(), changed);
  EXPECT_EQ(d.identity, (std::vector<ValueChange>{{"serial_number", "0", "1234"}}));
  EXPECT_EQ(d.options, (std::vector<ValueChange>{
                           {"response_time_ms", "80", "120"},
                           {"restart_mode", "start_restart_interlock", "start_interlock"},
                           {"start_pair", "1", "3"},
                           {"permitted.from_pair_1", "1, 2, 3, 4", "1, 2"},
                           {"warning_output", "contamination", "contamination, warning_field"},
                           {"measurement.stop", "528", "400"}}));
  EXPECT_EQ(d.passwords_changed, std::vector<int>{2});
  const std::string text = render_text(d);
  EXPECT_EQ(text,
            "identity serial_number: 0 -> 1234\n"
            "response_time_ms: 80 -> 120\n"
            "restart_mode: start_restart_interlock -> start_interlock\n"
            "start_pair: 1 -> 3\n"
            "permitted.from_pair_1: 1, 2, 3, 4 -> 1, 2\n"
            "warning_output: contamination -> contamination, warning_field\n"
            "measurement.stop: 528 -> 400\n"
            "user password 2 changed\n");
  EXPECT_EQ(render_json(d).find("HUNTER"), std::string::npos);
  EXPECT_NE(render_json(d).find(R"("passwords_changed":[2])"), std::string::npos);
}

}  // namespace
}  // namespace rs4sim::rs4::report
