// The RS4 from another GSD (rs4::adapter::GsdProfile, `rs4sim run --device rs4 --gsd FILE`):
// the adapter checks Chk_Cfg and the User_Prm_Data layout against the file it was given. The
// file is the project's tests/gsd/corpus/rs4_other_gsd.gsd; its header comment gives the bytes
// worked out by hand: Cfg B4 (normal format: 5 bytes in and out, consistent [IEC 61158-6-3
// Chk_Cfg/Get_Cfg]), User_Prm_Data 80 24 0B | 00 | 0E 05 00 00 | 14 00 00 01 01 F8 00 96 CRC1.
#include "adapter_rig.h"
#include "gsd/config.h"
#include "gsd/interp.h"
#include "tests/gsd/test_util.h"

namespace rs4sim::rs4::adapter::testing {
namespace {

using Bytes = std::vector<std::uint8_t>;

gsd::Device other_gsd() {
  auto d = gsd::parse(gsd::testing::corpus("rs4_other_gsd.gsd"), "rs4_other_gsd.gsd");
  EXPECT_TRUE(d) << d.error().what();
  return std::move(d).value();
}

AdapterConfig with(const GsdProfile& p) {
  AdapterConfig c;
  c.gsd = std::make_shared<const GsdProfile>(p);
  return c;
}

// The Set_Prm user data after DPV1_Status_1..3, as the file lays it out: the constant module
// byte, the block header naming slot 0, the F-parameters (the CRC1 from profisafe/).
dp::pdu::SetPrm other_layout(const profisafe::FParameters& p) {
  dp::pdu::SetPrm prm;
  prm.ident_number = 0x7A51;
  prm.user_data = {0x00, 0x0E, 0x05, 0x00, 0x00};
  for (auto b : profisafe::encode_f_parameters(p)) prm.user_data.push_back(b);
  return prm;
}

TEST(GsdProfile, TheBuiltInFilesLayout) {
  const GsdProfile& p = builtin_profile();
  EXPECT_EQ(p.slave.ident_number, 0x5234);
  EXPECT_EQ(p.module, "RS4/PROFIsafe F-I/O (1 byte)");
  EXPECT_EQ(p.cfg, (Bytes{0xC0, 0x84, 0x84}));
  EXPECT_EQ(p.user_prm_len, 14u);  // 17 bytes with DPV1_Status_1..3
  EXPECT_EQ(p.f_block_offset, 0u);
  EXPECT_EQ(p.f_block_header, (std::array<std::uint8_t, 4>{0x0E, 0x05, 0x01, 0x00}));
}

TEST(GsdProfile, AnotherFilesIdentCfgAndLayout) {
  const auto d = other_gsd();
  const auto p = gsd_profile(d, "", "rs4_other_gsd.gsd");  // the compact station's one module
  ASSERT_TRUE(p) << p.error().what();
  EXPECT_EQ(p.value().slave.ident_number, 0x7A51);
  EXPECT_EQ(p.value().module, "Scanner F-I/O");
  EXPECT_EQ(p.value().cfg, (Bytes{0xB4}));
  EXPECT_EQ(p.value().user_prm_len, 15u);
  EXPECT_EQ(p.value().f_block_offset, 1u);
  EXPECT_EQ(p.value().f_block_header, (std::array<std::uint8_t, 4>{0x0E, 0x05, 0x00, 0x00}));
  // What a master configured from the file sends is those bytes (F-parameter defaults: flags 14
  // 00, F_Source_Add 1, F_Dest_Add 504, F_WD_Time 150 ms).
  const auto setup = gsd::configure(d, {});
  ASSERT_TRUE(setup);
  const Bytes& u = setup.value().user_prm_data;
  ASSERT_EQ(u.size(), 18u);
  EXPECT_EQ(Bytes(u.begin(), u.begin() + 16), (Bytes{0x80, 0x24, 0x0B, 0x00, 0x0E, 0x05, 0x00, 0x00,
                                                     0x14, 0x00, 0x00, 0x01, 0x01, 0xF8, 0x00, 0x96}));
}

// Checked against the file it was given: its Cfg and layout are accepted, the built-in ones
// refused (Cfg_Fault; Prm_Fault without a PROFIsafe status PDU), and the F-parameters inside
// the block still go to the RS4's F-device with its own rules (F_Dest_Add 505 → 66).
TEST(GsdProfile, TheAdapterChecksAgainstTheFileItWasGiven) {
  const auto d = other_gsd();
  const auto p = gsd_profile(d, "Scanner F-I/O", "rs4_other_gsd.gsd");
  ASSERT_TRUE(p) << p.error().what();
  Rig rig(with(p.value()));
  rig.adapter.power_on(rig.now);
  rig.advance(3s);
  EXPECT_EQ(rig.adapter.check_config(Bytes{0xB4}, false, rig.now),
            dp::slave::CfgVerdict::kAccept);
  EXPECT_EQ(rig.adapter.check_config(kRealConfig, false, rig.now),
            dp::slave::CfgVerdict::kCfgFault);
  EXPECT_EQ(rig.adapter.check_parameters(set_prm_for(rs4_fparams()), rig.now),
            dp::slave::PrmVerdict::kPrmFault);
  EXPECT_TRUE(rig.control.diagnosis.empty());  // not the file's layout: no status PDU
  EXPECT_EQ(rig.adapter.check_parameters(other_layout(rs4_fparams(505)), rig.now),
            dp::slave::PrmVerdict::kPrmFault);
  EXPECT_EQ(rig.control.diagnosis, (Bytes{0x05, 0x81, 0x00, 0x00, 66}));  // [RS4 manual §6.3]
  EXPECT_EQ(rig.adapter.check_parameters(other_layout(rs4_fparams()), rig.now),
            dp::slave::PrmVerdict::kAccept);
  EXPECT_EQ(rig.control.diagnosis, (Bytes{0x05, 0x81, 0x00, 0x00, 0x00}));
}

// The built-in adapter refuses the other file's bytes.
TEST(GsdProfile, TheBuiltInAdapterRefusesTheOtherLayout) {
  Rig rig;
  rig.adapter.power_on(rig.now);
  rig.advance(3s);
  EXPECT_EQ(rig.adapter.check_config(Bytes{0xB4}, false, rig.now),
            dp::slave::CfgVerdict::kCfgFault);
  EXPECT_EQ(rig.adapter.check_parameters(other_layout(rs4_fparams()), rig.now),
            dp::slave::PrmVerdict::kPrmFault);
}

// A module that is not the RS4's: its I/O lengths or its missing F-parameter block named.
TEST(GsdProfile, AModuleThatIsNotAnRs4IsRefusedWithTheReason) {
  const std::string text =
      "#Profibus_DP\nGSD_Revision = 5\nIdent_Number = 0x1111\n12M_supp = 1\nMaxTsdr_12M = 200\n"
      "Modular_Station = 1\nMax_Module = 1\nMax_User_Prm_Data_Len = 0\n"
      "Module = \"DI 8\" 0x10\nEndModule\nModule = \"IO 5\" 0xB4\nEndModule\n";
  const auto d = gsd::parse(text, "x.gsd");
  ASSERT_TRUE(d) << d.error().what();
  const auto small = gsd_profile(d.value(), "DI 8", "x.gsd");
  ASSERT_FALSE(small);
  EXPECT_EQ(small.error().code, gsd::GsdError::kBadValue);
  EXPECT_EQ(small.error().what(),
            "x.gsd: module \"DI 8\" exchanges 1 input and 0 output bytes; the RS4/PROFIsafe "
            "exchanges 5 each way (the PROFIsafe V1 PDU: data, status/control, consecutive "
            "number, CRC2) [RS4 manual §5.1]");
  const auto no_f = gsd_profile(d.value(), "IO 5", "x.gsd");
  ASSERT_FALSE(no_f);
  EXPECT_EQ(no_f.error().code, gsd::GsdError::kFParameterLayout);
  EXPECT_NE(no_f.error().what().find("has no F-parameter block"), std::string::npos)
      << no_f.error().what();
  const auto unknown = gsd_profile(d.value(), "AO 2", "x.gsd");
  ASSERT_FALSE(unknown);
  EXPECT_EQ(unknown.error().code, gsd::GsdError::kUnknownModule);
}

}  // namespace
}  // namespace rs4sim::rs4::adapter::testing
