// The --mode word list (gridscan/mode_spec.h): the delivery mode and t_CYCLE from the user,
// held to the manual's band: "t_CYCLE ... 22 elements 18 30 40 ms; 60 elements 48 62 76 ms"
// (min, typ, max) [GridScan manual §11], both sides of both ends.
#include "gridscan/mode_spec.h"

#include <gtest/gtest.h>

#include <chrono>

namespace rs4sim::gridscan {
namespace {

using namespace std::chrono_literals;

Options with_elements(unsigned n) {
  Options o;
  o.elements = n;
  return o;
}

TEST(GridScanModeSpec, DeliveryModeWords) {
  Options o;
  EXPECT_EQ(apply_mode_spec("static", o), "");
  EXPECT_EQ(o.configuration, Configuration::kStatic);
  EXPECT_EQ(apply_mode_spec("blanking", o), "");
  EXPECT_EQ(o.configuration, Configuration::kBlanking);
  EXPECT_EQ(apply_mode_spec("door", o), "'door': use blanking or static");
  EXPECT_EQ(apply_mode_spec("static,fast", o),
            "'fast' is none of cycle= (after blanking or static)");
}

TEST(GridScanModeSpec, CycleInsideTheManualsBandAt22Elements) {
  Options o = with_elements(22);
  EXPECT_EQ(apply_mode_spec("blanking,cycle=18", o), "");
  EXPECT_EQ(o.cycle_time(), 18ms);
  EXPECT_EQ(apply_mode_spec("blanking,cycle=40", o), "");
  EXPECT_EQ(o.cycle_time(), 40ms);
  EXPECT_EQ(apply_mode_spec("blanking,cycle=17", o),
            "'cycle=17': t_CYCLE 17 ms outside 18..40 ms for 22 elements [GridScan manual §11]");
  EXPECT_EQ(apply_mode_spec("blanking,cycle=41", o),
            "'cycle=41': t_CYCLE 41 ms outside 18..40 ms for 22 elements [GridScan manual §11]");
  EXPECT_EQ(apply_mode_spec("blanking,cycle=x", o),
            "'cycle=x': cycle= takes milliseconds, e.g. cycle=30");
  EXPECT_EQ(o.cycle_time(), 40ms);  // the refusals changed nothing
}

TEST(GridScanModeSpec, CycleBandAt60ElementsAndBetween) {
  Options o = with_elements(60);
  EXPECT_EQ(apply_mode_spec("static,cycle=48", o), "");
  EXPECT_EQ(apply_mode_spec("static,cycle=76", o), "");
  EXPECT_NE(apply_mode_spec("static,cycle=47", o), "");
  EXPECT_NE(apply_mode_spec("static,cycle=77", o), "");
  // 41 elements, halfway: min 18 + 19*30/38 = 33 ms, max 40 + 19*36/38 = 58 ms (DECISION).
  EXPECT_EQ(cycle_range(41).min, 33ms);
  EXPECT_EQ(cycle_range(41).max, 58ms);
  EXPECT_EQ(check_cycle(41, 32ms),
            "t_CYCLE 32 ms outside 33..58 ms for 41 elements [GridScan manual §11]");
  // 23 elements: 18.789 ms .. 40.947 ms.
  EXPECT_EQ(check_cycle(23, 18ms),
            "t_CYCLE 18 ms outside 18.789..40.947 ms for 23 elements [GridScan manual §11]");
}

}  // namespace
}  // namespace rs4sim::gridscan
