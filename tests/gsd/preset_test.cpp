// The station's slot list ([PROFIBUS GSD spec modules, SlotDefinition]): preset modules ahead of
// the user's, a modular station with one module, names typed without the vendor's padding, and
// the F-parameter defaults `rs4sim gsd check` shows. preset_im153_style.gsd is the project's own
// file; its header comment gives the bytes worked out by hand.
#include "gsd/config.h"
#include "gsd/interp.h"
#include "test_util.h"

#include <gtest/gtest.h>

namespace rs4sim::gsd {
namespace {

using Bytes = std::vector<std::uint8_t>;
using testing::minimal;

Device parse_ok(const std::string& text, const std::string& name) {
  auto d = parse(text, name);
  EXPECT_TRUE(d) << (d ? "" : d.error().what());
  return d ? std::move(d).value() : Device{};
}

TEST(GsdPresets, PlacedAheadOfTheUsersModules) {
  const Device d = parse_ok(testing::corpus("preset_im153_style.gsd"), "p.gsd");
  EXPECT_TRUE(d.fix_preset_modules);
  const auto c = configure(d, {{"DI 16", "DO 8"}, {}});
  ASSERT_TRUE(c) << c.error().what();
  EXPECT_EQ(c.value().cfg, (Bytes{0x04, 0x00, 0x00, 0xAD, 0xC4, 0x04, 0x00, 0x00, 0x8B, 0x41, 0x04,
                                  0x00, 0x00, 0x8F, 0xC0, 0x11, 0x20}));
  EXPECT_EQ(c.value().input_len, 2U);
  EXPECT_EQ(c.value().output_len, 1U);
  EXPECT_EQ(c.value().user_prm_data, (Bytes{0x00, 0x00, 0x00, 0x01}));
  ASSERT_EQ(c.value().slots.size(), 5U);
  EXPECT_TRUE(c.value().slots[2].preset);
  EXPECT_FALSE(c.value().slots[3].preset);
  EXPECT_EQ(c.value().slots[0].slot, 1);  // Modul_Offset = 1
  EXPECT_EQ(c.value().slots[4].slot, 5);
  EXPECT_EQ(c.value().modules[3], "DI 16");
  // Without a user module: the presets alone.
  const auto presets = configure(d, {});
  ASSERT_TRUE(presets) << presets.error().what();
  EXPECT_EQ(presets.value().cfg.size(), 15U);
}

TEST(GsdPresets, APresetIsNotAUsersModule) {
  const Device d = parse_ok(testing::corpus("preset_im153_style.gsd"), "p.gsd");
  const auto c = configure(d, {{"Config for Slot1", "DI 16"}, {}});
  ASSERT_FALSE(c);
  EXPECT_EQ(c.error().code, GsdError::kUnknownModule);
  EXPECT_EQ(c.error().message,
            "\"Config for Slot1\" is a preset module (Preset = 1), placed ahead of the user's "
            "modules already: --module names the modules after the presets (modules: \"DI 16\", "
            "\"DO 8\")");
  const auto unknown = configure(d, {{"DI 32"}, {}});
  ASSERT_FALSE(unknown);
  EXPECT_EQ(unknown.error().message,
            "no module \"DI 32\" in the GSD (modules: \"DI 16\", \"DO 8\")");
}

TEST(GsdPresets, MaxModuleCountsThePresets) {
  const Device d = parse_ok(minimal("Modular_Station = 1\nMax_Module = 2\n"
                                    "Module = \"P\" 0x00\nPreset = 1\nEndModule\n"
                                    "Module = \"A\" 0x10\nEndModule\n"),
                            "m.gsd");
  EXPECT_TRUE(configure(d, {{"A"}, {}}));
  const auto c = configure(d, {{"A", "A"}, {}});
  ASSERT_FALSE(c);
  EXPECT_EQ(c.error().message, "a modular station takes 1..2 modules (Max_Module), got 3");
}

TEST(GsdPresets, AModularStationWithOneModuleTakesIt) {
  const Device d = parse_ok(minimal("Modular_Station = 1\nMax_Module = 1\n"
                                    "Module = \"Meter   \" 0x5F\nEndModule\n"),
                            "m.gsd");
  const auto c = configure(d, {});
  ASSERT_TRUE(c) << c.error().what();
  EXPECT_EQ(c.value().cfg, Bytes{0x5F});
  // Named as a user types it: without the padding, in any case.
  EXPECT_TRUE(configure(d, {{"meter"}, {}}));
  EXPECT_TRUE(configure(d, {{" Meter "}, {}}));
  // Two modules: the user chooses.
  const Device two = parse_ok(minimal("Modular_Station = 1\nMax_Module = 2\n"
                                      "Module = \"A\" 0x10\nEndModule\nModule = \"B\" 0x20\n"
                                      "EndModule\n"),
                              "m.gsd");
  const auto none = configure(two, {});
  ASSERT_FALSE(none);
  EXPECT_EQ(none.error().message, "choose the module(s) to configure (modules: \"A\", \"B\")");
}

TEST(GsdPresets, AnExactNameWinsOverAPaddedOne) {
  const Device d = parse_ok(minimal("Modular_Station = 1\nMax_Module = 2\n"
                                    "Module = \"A \" 0x10\nEndModule\nModule = \"A\" 0x20\n"
                                    "EndModule\n"),
                            "m.gsd");
  ASSERT_EQ(d.warnings.size(), 1U);  // the second is named as the first
  EXPECT_EQ(d.warnings[0].what(),
            "m.gsd:9: module \"A\" already defined at line 7; a --module of this name takes the "
            "first: `Module = \"A\" 0x20`");
  EXPECT_EQ(configure(d, {{"A"}, {}}).value().cfg, Bytes{0x20});
  EXPECT_EQ(configure(d, {{"A "}, {}}).value().cfg, Bytes{0x10});
}

TEST(GsdSlots, DefaultsFillTheSlotsTheUserLeavesEmpty) {
  const Device d = parse_ok(minimal("Modular_Station = 1\nMax_Module = 3\nModul_Offset = 1\n"
                                    "Module = \"A\" 0x10\n1\nEndModule\n"
                                    "Module = \"B\" 0x20\n2\nEndModule\n"
                                    "Module = \"C\" 0x30\n3\nEndModule\n"
                                    "SlotDefinition\nSlot(1) = \"first\" 1 1-2\n"
                                    "Slot(2) = \"second\" 3 2,3\nEndSlotDefinition\n"),
                            "s.gsd");
  ASSERT_EQ(d.slots.size(), 2U);
  EXPECT_EQ(d.slots[0].allowed, (std::vector<std::uint32_t>{1, 2}));
  EXPECT_EQ(configure(d, {}).value().cfg, (Bytes{0x10, 0x30}));
  EXPECT_EQ(configure(d, {{"B"}, {}}).value().cfg, (Bytes{0x20, 0x30}));
  EXPECT_EQ(configure(d, {{"B", "B", "A"}, {}}).value().cfg, (Bytes{0x20, 0x20, 0x10}));
  const auto refused = configure(d, {{"A", "A"}, {}});
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error().message,
            "slot 2 (\"second\") takes \"B\", \"C\", not \"A\" (SlotDefinition)");
}

TEST(GsdSlots, ASlotNamingNoModuleIsLeftOutWithAWarning) {
  const Device d = parse_ok(minimal("Modular_Station = 1\nModule = \"A\" 0x10\n1\nEndModule\n"
                                    "SlotDefinition\nSlot(1) = \"x\" 7 7\nEndSlotDefinition\n"),
                            "s.gsd");
  EXPECT_TRUE(d.slots.empty());
  ASSERT_EQ(d.warnings.size(), 1U);
  EXPECT_EQ(d.warnings[0].what(),
            "s.gsd:10: Slot(1): no module has the reference number 7; line ignored: "
            "`Slot(1) = \"x\" 7 7`");
}

TEST(GsdFParameters, DefaultsAndTheirCrc1) {
  const Device d = parse_ok(testing::corpus("profisafe_v2.gsd"), "profisafe_v2.gsd");
  const auto f = f_parameter_defaults(d, d.modules.at(0));
  ASSERT_TRUE(f) << f.error().what();
  // The file's header comment: the defaults give 08 40 00 01 00 01 00 96.
  const Bytes head(f.value().block.begin(), f.value().block.begin() + 8);
  EXPECT_EQ(head, (Bytes{0x08, 0x40, 0x00, 0x01, 0x00, 0x01, 0x00, 0x96}));
  EXPECT_EQ(f.value().crc1, testing::reference_crc1(head));
  EXPECT_EQ(f.value().file_crc, (f.value().block[8] << 8) | f.value().block[9]);
  EXPECT_FALSE(f_parameter_defaults(d, Module{}));  // no F-parameters
}

}  // namespace
}  // namespace rs4sim::gsd
