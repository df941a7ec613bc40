// The GSD file rs4sim ships (gsd/files/RSIM5234.gsd) and its built-in copy.
#include "gsd/config.h"
#include "gsd/device_gsd.h"
#include "gsd/interp.h"
#include "test_util.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace rs4sim::gsd {
namespace {

TEST(GsdShipped, BuiltInCopyIsTheFileByteForByte) {
  EXPECT_EQ(rs4sim_gsd_text(), testing::read_file(RS4SIM_GSD_SHIPPED));
}

TEST(GsdShipped, IsPlainAsciiWithCrlfLineEnds) {
  const std::string_view text = rs4sim_gsd_text();
  std::size_t lines = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    ASSERT_TRUE(c == '\r' || c == '\n' || (c >= 0x20 && c < 0x7F)) << "byte " << i;
    if (c == '\n') {
      ++lines;
      ASSERT_TRUE(i > 0 && text[i - 1] == '\r') << "LF without CR at byte " << i;
    }
  }
  EXPECT_GT(lines, 100U);
  EXPECT_EQ(text.back(), '\n');
}

TEST(GsdShipped, ParsesWithOurParser) {
  const auto& d = rs4sim_device();
  ASSERT_TRUE(d) << d.error().what();
  const Device& dev = d.value();
  EXPECT_EQ(dev.file, "RSIM5234.gsd");
  EXPECT_GE(dev.gsd_revision, 4);
  EXPECT_EQ(dev.ident_number, kRs4simIdentNumber);
  EXPECT_NE(dev.model_name.find("rs4sim"), std::string::npos);
  EXPECT_FALSE(dev.modular_station);
  EXPECT_EQ(dev.max_diag_data_len, 32);
}

TEST(GsdShipped, SupportsAllDpBaudRatesWithMaxTsdr) {
  const Device& dev = rs4sim_device().value();
  const std::pair<std::uint32_t, std::uint16_t> expected[] = {
      {9600, 15},   {19200, 15},   {45450, 15},   {93750, 15},    {187500, 15},
      {500000, 15}, {1500000, 25}, {3000000, 50}, {6000000, 100}, {12000000, 200}};
  for (const auto& [bps, tsdr] : expected) {
    const BaudRate* b = dev.find_baud(bps);
    ASSERT_NE(b, nullptr) << bps;
    EXPECT_TRUE(b->supported) << bps;
    EXPECT_EQ(b->max_tsdr, tsdr) << bps;
  }
}

TEST(GsdShipped, Dpv1Capabilities) {
  const Dpv1Info& v = rs4sim_device().value().dpv1;
  EXPECT_TRUE(v.slave);
  EXPECT_TRUE(v.c1_read_write);
  EXPECT_TRUE(v.c2_read_write);
  EXPECT_EQ(v.c1_max_data_len, 240);
  EXPECT_EQ(v.c2_max_data_len, 240);
  EXPECT_EQ(v.c1_response_timeout, 100);
  EXPECT_TRUE(v.diagnostic_alarm);
  EXPECT_TRUE(v.update_alarm);
  EXPECT_FALSE(v.process_alarm);
  EXPECT_EQ(v.alarm_sequence_mode_count, 8);  // [RS4 manual §5.3]: sequence mode, 8 alarms
}

TEST(GsdShipped, OneProfisafeModuleOf5BytesEachWay) {
  const Device& dev = rs4sim_device().value();
  ASSERT_EQ(dev.modules.size(), 1U);
  const Module& m = dev.modules[0];
  EXPECT_EQ(m.name, kRs4simModuleName);
  // [PROFIsafe V1.30 safety PDU]: 1 data byte + status/control + consecutive number + CRC2 (2).
  EXPECT_EQ(m.input_len, 5U);
  EXPECT_EQ(m.output_len, 5U);
  ASSERT_TRUE(m.f_prm.has_value());
  EXPECT_EQ(m.f_prm->length, 14U);
}

TEST(GsdShipped, FParameterRangesAndDefaultsFollowTheManual) {
  // [RS4 manual §6.2, §6.3].
  const Device& dev = rs4sim_device().value();
  std::map<std::string, const ExtParam*> by_name;
  for (const auto& [n, p] : dev.params) by_name[p.name] = &p;
  const struct {
    const char* name;
    std::int64_t def, min, max;
    bool changeable;
  } expected[] = {
      {"F_Check_SeqNr", 0, 0, 1, true},    {"F_Check_iPar", 0, 0, 0, false},
      {"F_SIL", 1, 1, 1, false},           {"F_CRC_Length", 1, 1, 1, false},
      {"F_Block_ID", 0, 0, 0, false},      {"F_Par_Version", 0, 0, 0, false},
      {"F_Source_Add", 1, 1, 65534, true}, {"F_Dest_Add", 504, 500, 626, true},
      {"F_WD_Time", 10, 10, 1000, true},
  };
  for (const auto& e : expected) {
    ASSERT_TRUE(by_name.count(e.name)) << e.name;
    const ExtParam& p = *by_name[e.name];
    EXPECT_EQ(p.default_value, e.def) << e.name;
    EXPECT_EQ(p.min, e.min) << e.name;
    EXPECT_EQ(p.max, e.max) << e.name;
    EXPECT_EQ(p.changeable, e.changeable) << e.name;
  }
  EXPECT_EQ(dev.prm_texts.at(by_name["F_SIL"]->prm_text_ref.value()).texts.at(1), "SIL2");
}

TEST(GsdShipped, DefaultFParCrcInTheFileIsTheCrc1OfTheDefaults) {
  const Device& dev = rs4sim_device().value();
  auto c = configure(dev, {});
  ASSERT_TRUE(c);
  const Module& m = dev.modules[0];
  // The const bytes +12..+13 of the F block and the ExtUserPrmData default must agree
  // with what the configuration computes for the default values.
  EXPECT_EQ(m.f_prm->defaults[12] << 8 | m.f_prm->defaults[13],
            c.value().f_parameters[0].parameters.par_crc);
  for (const auto& [n, p] : dev.params) {
    if (p.name == "F_Par_CRC") {
      EXPECT_EQ(p.default_value, c.value().f_parameters[0].parameters.par_crc);
    }
  }
}

TEST(GsdShipped, LayoutConstantsMatchTheConfiguration) {
  auto c = configure(rs4sim_device().value(), {});
  ASSERT_TRUE(c);
  const auto& prm = c.value().user_prm_data;
  ASSERT_EQ(prm.size(), kRs4simUserPrmDataLen);
  EXPECT_TRUE(std::equal(kRs4simDpv1Status.begin(), kRs4simDpv1Status.end(), prm.begin()));
  EXPECT_TRUE(std::equal(kRs4simFBlockHeader.begin(), kRs4simFBlockHeader.end(),
                         prm.begin() + kRs4simFBlockHeaderOffset));
  EXPECT_EQ(c.value().f_parameters[0].offset, kRs4simFParametersOffset);
  EXPECT_TRUE(
      std::equal(kRs4simCfg.begin(), kRs4simCfg.end(), c.value().cfg.begin(), c.value().cfg.end()));
}

TEST(GsdShipped, FParamDescCrcMatchesTheProjectsDefinition) {
  const Device& dev = rs4sim_device().value();
  const Module& m = dev.modules[0];
  ASSERT_TRUE(m.f_param_desc_crc.has_value());
  EXPECT_EQ(*m.f_param_desc_crc, f_param_desc_crc(dev, m));
}

TEST(GsdShipped, FParamDescCrcChangesWhenADescriptionChanges) {
  std::string text(rs4sim_gsd_text());
  const std::string from = "Unsigned16 10 10-1000";
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, from.size(), "Unsigned16 10 10-2000");
  auto changed = parse(text, "changed.gsd");
  ASSERT_TRUE(changed) << changed.error().what();
  const Device& dev = rs4sim_device().value();
  EXPECT_NE(f_param_desc_crc(changed.value(), changed.value().modules[0]),
            f_param_desc_crc(dev, dev.modules[0]));
}

}  // namespace
}  // namespace rs4sim::gsd
