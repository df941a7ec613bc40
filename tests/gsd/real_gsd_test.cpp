// Every real GSD file of the project's real material (GSD files of several makers that nobody on
// the project wrote; tests/gsd/real_files.h says where they are looked for), read as a user's
// own file is read. The expected facts were worked out by hand from each file (the module's Cfg
// byte decoded bit by bit, the User_Prm_Data built from its Const and Ref lines), not copied
// from rs4sim's output. Skipped with a message where the material is absent (a user's clone).
#include "gsd/config.h"
#include "gsd/interp.h"
#include "real_files.h"
#include "test_util.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>

namespace rs4sim::gsd {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<std::uint8_t>;

struct Expected {
  const char* file;
  std::uint16_t ident;
  std::vector<std::string> modules;  // the user's modules (empty: the default configuration)
  Bytes cfg;                         // Chk_Cfg
  std::size_t input_len, output_len;
  Bytes user_prm_data;
};

// Worked out by hand (docs/gsd.md "Real files"):
const std::vector<Expected>& expected() {
  static const std::vector<Expected> kFiles = {
      // compact; 0xFF = consistent, words, in and out, 16 words: 32 bytes each way
      {"kfc750.gsd", 0x7050, {}, {0xFF}, 32, 32, {}},
      // the three modules of its header comment: 00 (no data), 10, 10 (1 input byte each)
      {"si0180e0-trimmed.gsd",
       0x80E0,
       {"PM-E DC24V", "4DI DC24V", "4DI DC24V"},
       {0x00, 0x10, 0x10},
       2,
       0,
       {}},
      // 0xF0 = consistent, words, in and out, 1 word; Const 00 00 00 00 10 00 01 00 00 00 with
      // byte 1 = Bit(1) "Class 2" 1 + Bit(3) "Scaling" 1 = 0x0A, 4096 and 16777216 as written
      {"TR09AAAB.GSE",
       0xAAAB,
       {"PNO Class 2  16 Bit"},
       {0xF0},
       2,
       2,
       {0x00, 0x0A, 0x00, 0x00, 0x10, 0x00, 0x01, 0x00, 0x00, 0x00}},
      // SlotDefinition defaults AI16 (0x50: words, input, 1 word), DI8 (0x10), DO8 (0x20);
      // 00 00 00 global, AI16 1F 40 F0 60 (0x1f40, 0xf060), DO8 Const 03 with Bit(0), Bit(1) 0
      {"DPV10008.gsd",
       0x0008,
       {},
       {0x50, 0x10, 0x20},
       3,
       1,
       {0x00, 0x00, 0x00, 0x1F, 0x40, 0xF0, 0x60, 0x00}},
      // 0x31 = in and out, 2 bytes
      {"EASY4711.gsd", 0x4711, {}, {0x31}, 2, 2, {0x00, 0x00, 0x00}},
      // 0x17 = input 8 bytes, 0x27 = output 8 bytes; the name has a trailing blank
      {"PRU_0CDA.GSD", 0x0CDA, {"8 Byte Out, 8 Byte In"}, {0x17, 0x27}, 8, 8, {0x00, 0x00, 0x00}},
      // Const 05 00 under Ref(0) "HW version (High)" and Ref(1) "(Low)", both default 0; the
      // module's Const 20 00 00 under BitArea defaults 0
      {"lego0005.gsd",
       0x0005,
       {"8 bit Output Module"},
       {0x20},
       0,
       1,
       {0x00, 0x00, 0x20, 0x00, 0x00}},
      {"mega0004.gsd",
       0x0004,
       {"1 byte Output Module"},
       {0x20},
       0,
       1,
       {0x00, 0x00, 0x21, 0x00, 0x00}},
      // its one module is a preset: 22 (out 3), 20, 20 (out 1 each), 10, 10 (in 1 each)
      {"STM32F1002A.gsd", 0x002A, {}, {0x22, 0x20, 0x20, 0x10, 0x10}, 2, 5, {}},
      // 0x42 with Bit(2), Bit(3) default 0
      {"pyprofibus-dummy_compact.gsd",
       0x4224,
       {"dummy input module"},
       {0x10},
       1,
       0,
       {0x00, 0x00, 0x00, 0x42}},
      // the preset "fixed module" (00) first, then the user's
      {"pyprofibus-dummy_modular.gsd",
       0x4224,
       {"dummy input module", "dummy output module"},
       {0x00, 0x10, 0x20},
       1,
       1,
       {0x00, 0x00, 0x00, 0x42}},
  };
  return kFiles;
}

TEST(GsdRealFiles, EveryFileIsReadAndConfiguredAsWorkedOutByHand) {
  const auto dir = testing::real_gsd_dir();
  if (!dir) GTEST_SKIP() << testing::real_gsd_skip_message();
  std::set<std::string> checked;
  for (const auto& e : expected()) {
    SCOPED_TRACE(e.file);
    const auto d = parse(testing::read_file((*dir / e.file).string()), e.file);
    ASSERT_TRUE(d) << d.error().what();
    EXPECT_EQ(d.value().ident_number, e.ident);
    const auto c = configure(d.value(), {e.modules, {}});
    ASSERT_TRUE(c) << c.error().what();
    EXPECT_EQ(c.value().cfg, e.cfg);
    EXPECT_EQ(c.value().input_len, e.input_len);
    EXPECT_EQ(c.value().output_len, e.output_len);
    EXPECT_EQ(c.value().user_prm_data, e.user_prm_data);
    checked.insert(e.file);
  }
  // Every file of the folder is one of the above: none is refused (none needs to be, by the
  // rule of docs/gsd.md), and a file added later fails here until its facts are written.
  for (const auto& entry : fs::directory_iterator(*dir)) {
    EXPECT_TRUE(checked.count(entry.path().filename().string())) << entry.path();
  }
}

Device real(const char* name) {
  const auto dir = testing::real_gsd_dir();
  auto d = parse(testing::read_file((*dir / name).string()), name);
  EXPECT_TRUE(d) << d.error().what();
  return d ? std::move(d).value() : Device{};
}

TEST(GsdRealFiles, SubFamiliesWithBlanks) {
  if (!testing::real_gsd_dir()) GTEST_SKIP() << testing::real_gsd_skip_message();
  const Device d = real("EASY4711.gsd");  // Slave_Family = 3@profichip GmbH@EvaKit_ATMEL89C5132
  EXPECT_EQ(d.slave_family, 3);
  EXPECT_EQ(d.sub_families, (std::vector<std::string>{"profichip GmbH", "EvaKit_ATMEL89C5132"}));
}

TEST(GsdRealFiles, LengthsBeyondATelegramAreTakenAtTheLimitWithAWarning) {
  if (!testing::real_gsd_dir()) GTEST_SKIP() << testing::real_gsd_skip_message();
  const Device d = real("pyprofibus-dummy_modular.gsd");
  EXPECT_EQ(d.max_input_len, 244);  // Max_Input_Len=249
  EXPECT_EQ(d.max_output_len, 244);
  EXPECT_EQ(d.max_data_len, 488);  // Max_Data_Len=498
  ASSERT_GE(d.warnings.size(), 3U);
  EXPECT_EQ(d.warnings[0].what(),
            "pyprofibus-dummy_modular.gsd:76: Max_Input_Len = 249 is out of range 0..244; 244 "
            "taken: `Max_Input_Len=249`");
  EXPECT_TRUE(d.fix_preset_modules);
}

TEST(GsdRealFiles, UpperCaseKeywordsAndAPresetModuleOfACompactStation) {
  if (!testing::real_gsd_dir()) GTEST_SKIP() << testing::real_gsd_skip_message();
  const Device d = real("STM32F1002A.gsd");  // FIXPRESETMODULES=1, PRESET=1
  EXPECT_TRUE(d.fix_preset_modules);
  ASSERT_EQ(d.modules.size(), 1U);
  EXPECT_TRUE(d.modules[0].preset);
  // The words that are no GSD keyword, each with its line: Subscriber_supp (50),
  // Min_Slave_Interval (53, the keyword is Min_Slave_Intervall), Module_Reference (55).
  std::vector<int> lines;
  for (const auto& w : d.warnings) lines.push_back(w.line);
  EXPECT_EQ(lines, (std::vector<int>{50, 53, 55}));
  // The user cannot name the preset again.
  const auto c = configure(d, {{"Servo,A0,DO,DI1,DI2"}, {}});
  ASSERT_FALSE(c);
  EXPECT_EQ(c.error().code, GsdError::kUnknownModule);
}

TEST(GsdRealFiles, XUnitDiagAreaInsideUnitDiagTypeAndSlotDefinition) {
  if (!testing::real_gsd_dir()) GTEST_SKIP() << testing::real_gsd_skip_message();
  const Device d = real("DPV10008.gsd");
  ASSERT_EQ(d.slots.size(), 3U);  // Slot(1) = "Slot 1" 1 1 …
  EXPECT_EQ(d.slots[1].name, "Slot 2");
  EXPECT_EQ(d.slots[1].default_ref, 2U);
  EXPECT_EQ(d.slots[1].allowed, (std::vector<std::uint32_t>{2}));
  // A module a slot does not allow is refused by name; one it allows, typed without the
  // file's padding ("DI8 (enable-status)    "), takes slot 1 only if slot 1 allows it.
  const auto wrong = configure(d, {{"DI8 (enable-status)"}, {}});
  ASSERT_FALSE(wrong);
  EXPECT_EQ(wrong.error().message,
            "slot 1 (\"Slot 1\") takes \"AI16 (temperature)   \", not \"DI8 (enable-status)    \" "
            "(SlotDefinition)");
  const auto typed = configure(d, {{"ai16 (temperature)"}, {}});
  ASSERT_TRUE(typed) << typed.error().what();
  EXPECT_EQ(typed.value().cfg, (Bytes{0x50, 0x10, 0x20}));
}

}  // namespace
}  // namespace rs4sim::gsd
