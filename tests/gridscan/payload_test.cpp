// State bytes, the door-blanking scene, LEDs and options
// ([GridScan manual §9.2.4, §6.1, §13, §4.3]).
#include "gridscan/payload.h"

#include "gridscan/leds.h"
#include "gridscan/options.h"
#include "gridscan/scene.h"

#include <gtest/gtest.h>

namespace rs4sim::gridscan {
namespace {

using namespace std::chrono_literals;
using P = std::vector<std::uint8_t>;

P bytes(const Payload& p) { return {p.begin(), p.end()}; }

TEST(GridScanPayload, StateBytes) {
  StateReport s{22, true, true, 3, 0};
  EXPECT_EQ(bytes(encode_reduced_state(s)), (P{0x16, 0xC3}));  // b8, b9, maintenance 3
  s = {0, false, false, 2, (1ULL << 59) | 1ULL};
  EXPECT_EQ(bytes(encode_full_state(s, 60)),
            (P{0x00, 0x80, 0x01, 0, 0, 0, 0, 0, 0, 0x08}));  // element 60 = bit 75
  EXPECT_EQ(bytes(encode_full_state({0, false, false, 0, ~0ULL}, 12)), (P{0, 0, 0xFF, 0x0F}));
  const P reserved{0x05, 0x3C, 0x02};  // reserved bits 10..13 masked out
  auto d = decode_state(reserved);
  ASSERT_TRUE(d);
  EXPECT_EQ(d.value(), (StateReport{5, false, false, 0, 0x02}));
  EXPECT_EQ(decode_state(P{0x01}).error(), FrameError::kPayloadLength);
}

TEST(GridScanPayload, InfoPayloads) {
  EXPECT_EQ(bytes(encode_product_information("116123", 22).value()),
            (P{'1', '1', '6', '1', '2', '3', 0, 0, 0, 22}));
  EXPECT_EQ(encode_product_information("11612", 22).error(), FrameError::kBadField);
  EXPECT_EQ(encode_version("1.2", "03.04").error(), FrameError::kBadField);
  EXPECT_EQ(bytes(encode_u16_le(0x1234)), (P{0x34, 0x12}));
}

TEST(GridScanScene, DoorBlanking) {
  Scene s;
  s.door_position = 10;    // elements 1..10 below the door edge
  s.blocked = 1ULL << 14;  // element 15: behind the door, blanked
  EXPECT_FALSE(interrupted_below_edge(s, 22, Configuration::kBlanking));
  EXPECT_TRUE(interrupted_below_edge(s, 22, Configuration::kStatic));
  EXPECT_EQ(raw_elements(s, 22, Configuration::kBlanking), element_mask(22) & ~element_mask(10));
  s.blocked = 1ULL << 9;  // element 10, the lowest active one... below the edge
  EXPECT_TRUE(interrupted_below_edge(s, 22, Configuration::kBlanking));
  const auto r = report_of(s, 22, Configuration::kStatic);
  EXPECT_EQ(r.door_position, 255);
  EXPECT_EQ(r.elements, 1ULL << 9);
  const auto all = all_interrupted_report(s, 22, Configuration::kBlanking);
  EXPECT_TRUE(all.interrupted);
  EXPECT_EQ(all.elements, element_mask(22));
  EXPECT_EQ(all.door_position, 10);
}

TEST(GridScanLeds, Table2And3) {
  EXPECT_EQ(leds_for({}), (Leds{}));
  EXPECT_EQ(leds_for({true, true}), (Leds{Led::kOff, Led::kBlinkSlow, Led::kOn}));
  EXPECT_EQ(leds_for({true, false, true}), (Leds{Led::kOff, Led::kBlinkFast, Led::kOn}));
  EXPECT_EQ(leds_for({true, false, false, true}), (Leds{Led::kBlink1Hz, Led::kOff, Led::kOn}));
  EXPECT_EQ(leds_for({true, false, false, false, true}), (Leds{Led::kOff, Led::kOn, Led::kOn}));
  EXPECT_EQ(leds_for({true}), (Leds{Led::kOn, Led::kOff, Led::kOn}));
  EXPECT_EQ(to_string(Led::kBlinkFast), "fast blink (5 Hz)");
}

TEST(GridScanOptions, ValidateNamesTheProblem) {
  Options o;
  EXPECT_EQ(o.validate(), "");
  EXPECT_EQ(o.cycle_time(), 30ms);
  o.elements = 60;
  EXPECT_EQ(o.cycle_time(), 62ms);
  o.elements = 61;
  EXPECT_EQ(o.validate(), "elements 61 outside 12..60");
  o = {};
  o.door_position = 23;
  EXPECT_EQ(o.validate(), "door position 23 outside 0..22");
  o = {};
  o.blocked = 1ULL << 22;
  EXPECT_EQ(o.validate(), "blocked elements beyond element 22");
  o = {};
  o.sw_version = "1.2.3";
  EXPECT_EQ(o.validate(), "SW version \"1.2.3\" is not xx.yy");
  o = {};
  o.part_number = "11600x";
  EXPECT_EQ(o.validate(), "part number \"11600x\" is not 6 digits");
  o = {};
  o.soiling = 4;
  EXPECT_EQ(o.validate(), "soiling level 4 outside 0..3");
  o = {};
  o.idle_gap_chars = 0.5;
  EXPECT_EQ(o.validate(), "idle gap outside 1..100 character times");
  o = {};
  o.cycle = 0ms;
  EXPECT_EQ(o.validate(), "cycle time outside 1 ms..1 s");
  EXPECT_EQ(Options{}.idle_gap(), 303820ns);  // 3.5 × 10 bits at 115200 bit/s, rounded up
}

}  // namespace
}  // namespace rs4sim::gridscan
