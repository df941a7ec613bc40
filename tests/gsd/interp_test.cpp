// GSD meaning ([PROFIBUS GSD spec]) of the corpus files under corpus/.
#include "gsd/interp.h"

#include "test_util.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <utility>

namespace rs4sim::gsd {
namespace {

Device load(const std::string& name) {
  auto d = parse(testing::corpus(name), name);
  EXPECT_TRUE(d) << (d ? "" : d.error().what());
  return d ? d.value() : Device{};
}

TEST(GsdInterp, CompactDpv0WithLegacyUserPrmData) {
  const Device d = load("compact_dpv0.gsd");
  EXPECT_EQ(d.ident_number, 0x1234);
  EXPECT_EQ(d.gsd_revision, 3);
  EXPECT_EQ(d.vendor_name, "Test vendor");
  EXPECT_FALSE(d.modular_station);
  EXPECT_FALSE(d.dpv1.slave);
  ASSERT_NE(d.find_baud(9600), nullptr);
  EXPECT_TRUE(d.find_baud(9600)->supported);
  EXPECT_EQ(d.find_baud(9600)->max_tsdr, 60);
  EXPECT_TRUE(d.find_baud(1500000)->supported);
  EXPECT_EQ(d.find_baud(1500000)->max_tsdr, 150);  // keyword written MaxTsdr_1.5m
  EXPECT_FALSE(d.find_baud(12000000)->supported);
  EXPECT_EQ(d.user_prm.length, 3U);
  EXPECT_EQ(d.user_prm.defaults, (std::vector<std::uint8_t>{0x01, 0x02, 0xFF}));
  ASSERT_EQ(d.modules.size(), 1U);
  EXPECT_EQ(d.modules[0].cfg, std::vector<std::uint8_t>{0x30});
  EXPECT_EQ(d.modules[0].input_len, 1U);  // 0x30: in+out, 1 byte each
                                          // ([IEC 61158-6-3 Chk_Cfg/Get_Cfg])
  EXPECT_EQ(d.modules[0].output_len, 1U);
}

// GSD revisions 1 and 2 ([PROFIBUS GSD spec GSD_Revision]): the same DP-V0 keywords as later
// revisions, read the same way; what they add over the revision before is rates. Revision 1:
// 3, 6 and 12 Mbit/s with their MaxTsdr_3M/6M/12M; revision 2: 45.45 kbit/s and 31.25 kbit/s
// (the MBP rate of PROFIBUS PA, behind a coupler: a known keyword that no RS-485 rate takes,
// so it is skipped without a warning). The DP-V1 keywords came with revision 3.
TEST(GsdInterp, Revision1ModularDpv0WithTheMegabitRates) {
  const Device d = load("revision1_modular.gsd");
  EXPECT_EQ(d.gsd_revision, 1);
  EXPECT_EQ(d.ident_number, 0x0A11);
  EXPECT_TRUE(d.warnings.empty());
  EXPECT_FALSE(d.dpv1.slave);
  EXPECT_TRUE(d.freeze_mode);
  EXPECT_TRUE(d.sync_mode);
  EXPECT_EQ(d.min_slave_interval, 6);
  EXPECT_EQ(d.max_diag_data_len, 8);
  const std::pair<std::uint32_t, int> megabit[] = {{3000000, 250}, {6000000, 450}, {12000000, 800}};
  for (const auto& [bps, tsdr] : megabit) {
    ASSERT_NE(d.find_baud(bps), nullptr) << bps;
    EXPECT_TRUE(d.find_baud(bps)->supported) << bps;
    EXPECT_EQ(d.find_baud(bps)->max_tsdr, tsdr) << bps;
  }
  EXPECT_FALSE(d.find_baud(45450)->supported);  // a revision 2 rate
  EXPECT_TRUE(d.modular_station);
  EXPECT_EQ(d.max_module, 4);
  EXPECT_EQ(d.user_prm.defaults, (std::vector<std::uint8_t>{0x00, 0x05}));
  ASSERT_EQ(d.modules.size(), 3U);                               // Cfg bytes written in decimal
  EXPECT_EQ(d.modules[0].cfg, std::vector<std::uint8_t>{0x10});  // 16: 1 input byte
  EXPECT_EQ(d.modules[0].input_len, 1U);
  EXPECT_EQ(d.modules[1].cfg, std::vector<std::uint8_t>{0x20});  // 32: 1 output byte
  EXPECT_EQ(d.modules[1].output_len, 1U);
  EXPECT_EQ(d.modules[2].cfg, std::vector<std::uint8_t>{0x51});  // 81: 2 input words
  EXPECT_EQ(d.modules[2].input_len, 4U);                         // [IEC 61158-6-3 Chk_Cfg/Get_Cfg]
}

TEST(GsdInterp, Revision2Compact45k45AndThePaRateSkipped) {
  const Device d = load("revision2_compact.gsd");
  EXPECT_EQ(d.gsd_revision, 2);
  EXPECT_EQ(d.ident_number, 0x0A22);
  EXPECT_TRUE(d.warnings.empty());  // 31.25_supp and MaxTsdr_31.25 are GSD keywords
  EXPECT_FALSE(d.dpv1.slave);
  ASSERT_NE(d.find_baud(45450), nullptr);
  EXPECT_TRUE(d.find_baud(45450)->supported);
  EXPECT_EQ(d.find_baud(45450)->max_tsdr, 250);
  EXPECT_EQ(d.find_baud(31250), nullptr);  // not one of the ten RS-485 DP rates
  EXPECT_FALSE(d.find_baud(12000000)->supported);
  EXPECT_FALSE(d.modular_station);
  ASSERT_EQ(d.modules.size(), 1U);
  EXPECT_EQ(d.modules[0].input_len, 1U);
  EXPECT_EQ(d.modules[0].output_len, 1U);
}

TEST(GsdInterp, ModularDpv1WithExtUserPrmData) {
  const Device d = load("modular_dpv1.gsd");
  EXPECT_EQ(d.ident_number, 0xB756);
  EXPECT_EQ(d.model_name, "Modular head DPV1");  // continued line, adjacent strings
  EXPECT_TRUE(d.modular_station);
  EXPECT_EQ(d.max_module, 4);
  EXPECT_TRUE(d.dpv1.slave);
  EXPECT_TRUE(d.dpv1.c1_read_write);
  EXPECT_EQ(d.dpv1.c1_max_data_len, 240);
  EXPECT_EQ(d.dpv1.c1_response_timeout, 1000);
  EXPECT_TRUE(d.dpv1.diagnostic_alarm);
  EXPECT_TRUE(d.dpv1.process_alarm);
  EXPECT_FALSE(d.dpv1.update_alarm);
  EXPECT_EQ(d.dpv1.alarm_sequence_mode_count, 4);
  EXPECT_TRUE(d.dpv1.wd_base_1ms);
  EXPECT_EQ(d.max_user_prm_data_len, 20);
  ASSERT_EQ(d.params.size(), 4U);
  const ExtParam& mode = d.params.at(2);
  EXPECT_EQ(mode.name, "Mode");
  EXPECT_EQ(mode.type, ParamType::kBitArea);
  EXPECT_EQ(mode.bit_low, 4);
  EXPECT_EQ(mode.bit_high, 6);
  EXPECT_EQ(mode.default_value, 3);
  EXPECT_EQ(mode.allowed, (std::vector<std::int64_t>{0, 1, 3, 5}));
  EXPECT_TRUE(mode.accepts(5));
  EXPECT_FALSE(mode.accepts(2));
  const ExtParam& offset = d.params.at(4);
  EXPECT_EQ(offset.type, ParamType::kSigned8);
  EXPECT_EQ(offset.default_value, -5);
  EXPECT_EQ(offset.range_text(), "-100..100");
  EXPECT_EQ(d.params.at(1).prm_text_ref, 1);
  EXPECT_EQ(d.prm_texts.at(1).texts.at(1), "enabled");
  EXPECT_EQ(d.user_prm.length, 4U);
  EXPECT_EQ(d.user_prm.refs.size(), 2U);
  ASSERT_EQ(d.modules.size(), 3U);
  const Module* ai = d.find_module("ai 2");  // names compare case-insensitively
  ASSERT_NE(ai, nullptr);
  EXPECT_EQ(ai->reference, 2U);
  EXPECT_EQ(ai->input_len, 4U);  // 0x51: input, words, 2 words
  EXPECT_EQ(ai->prm.length, 4U);
  EXPECT_EQ(ai->prm.defaults, (std::vector<std::uint8_t>{0xAA, 0, 0, 0}));
  EXPECT_EQ(d.find_module("DI 8")->info_text, "8 digital inputs");
  EXPECT_EQ(d.find_module("DO 16 consistent")->output_len, 2U);  // 0xA1: out, 2 bytes
}

TEST(GsdInterp, ProfisafeModuleWithFParameters) {
  const Device d = load("profisafe_v2.gsd");
  const Module* f = d.find_module("75x-661 4FDI");
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->reference, 6610U);
  EXPECT_EQ(f->input_len, 5U);  // 0xC4 0x84 0x84 + 4 manufacturer bytes
                                // ([IEC 61158-6-3 Chk_Cfg/Get_Cfg])
  EXPECT_EQ(f->output_len, 5U);
  EXPECT_EQ(f->prm.length, 3U);
  ASSERT_TRUE(f->f_prm.has_value());
  EXPECT_EQ(f->f_prm->length, 14U);
  EXPECT_EQ(f->f_prm->refs.size(), 11U);
  EXPECT_EQ(f->f_param_desc_crc, 3802);
  EXPECT_EQ(f->f_io_structure_desc_crc, 55196);
  EXPECT_FALSE(d.params.at(164).changeable);
  EXPECT_EQ(d.params.at(162).range_text(), "50..10000");
  const Module* empty = d.find_module("empty slot");
  ASSERT_NE(empty, nullptr);
  EXPECT_EQ(empty->input_len + empty->output_len, 0U);
}

TEST(GsdInterp, WhitespaceAndCommentsDoNotChangeMeaning) {
  const Device d = load("whitespace_comments.gsd");
  EXPECT_EQ(d.ident_number, 0x00FF);
  EXPECT_EQ(d.vendor_name, "semi;colon \\ inside");
  EXPECT_EQ(d.model_name, "tab");
  EXPECT_EQ(d.find_baud(500000)->max_tsdr, 100);
  ASSERT_EQ(d.modules.size(), 1U);
  EXPECT_EQ(d.modules[0].cfg, (std::vector<std::uint8_t>{0x13, 0x23}));
  EXPECT_EQ(d.modules[0].input_len, 4U);
  EXPECT_EQ(d.modules[0].output_len, 4U);
}

TEST(GsdInterp, UnknownKeywordsAreSkipped) {
  auto d = parse(testing::minimal("Bitmap_Device = \"X\"\nSome_Future_Key = 1,2,3\n"), "u.gsd");
  ASSERT_TRUE(d) << d.error().what();
  EXPECT_EQ(d.value().ident_number, 0x1234);
}

}  // namespace
}  // namespace rs4sim::gsd
