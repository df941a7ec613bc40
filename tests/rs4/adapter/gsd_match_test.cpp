// The adapter accepts exactly what the project's GSD configuration produces (docs/gsd.md):
// ident, Chk_Cfg and the User_Prm_Data after the DPV1 bytes.
#include "adapter_rig.h"
#include "gsd/config.h"
#include "gsd/device_gsd.h"

namespace rs4sim::rs4::adapter::testing {
namespace {

gsd::SlaveSetup configure(std::int64_t dest) {
  const auto& device = gsd::rs4sim_device();
  EXPECT_TRUE(device);
  gsd::ConfigRequest req;
  req.overrides.push_back({"F_Dest_Add", dest});
  req.overrides.push_back({"F_WD_Time", 1000});
  auto cfg = gsd::configure(device.value(), req);
  EXPECT_TRUE(cfg);
  return cfg.value();
}

dp::pdu::SetPrm from_gsd(const gsd::SlaveSetup& c) {
  dp::pdu::SetPrm prm;
  prm.ident_number = c.ident_number;
  prm.dpv1 =
      dp::pdu::Dpv1Status::from_bytes(c.user_prm_data[0], c.user_prm_data[1], c.user_prm_data[2]);
  for (std::size_t i = 3; i < c.user_prm_data.size(); ++i)
    prm.user_data.push_back(c.user_prm_data[i]);
  return prm;
}

TEST(GsdMatch, IdentCfgAndUserPrmOfTheShippedGsdAreAccepted) {
  const auto c = configure(504);
  EXPECT_EQ(c.ident_number, ident_number());
  EXPECT_EQ(c.cfg, std::vector<std::uint8_t>(kRealConfig.begin(), kRealConfig.end()));
  EXPECT_EQ(c.input_len, kPduSize);
  EXPECT_EQ(c.output_len, kPduSize);
  Rig rig;
  rig.adapter.power_on(rig.now);
  rig.advance(3s);
  EXPECT_EQ(rig.adapter.check_parameters(from_gsd(c), rig.now), dp::slave::PrmVerdict::kAccept);
  EXPECT_EQ(rig.adapter.check_config(c.cfg, false, rig.now), dp::slave::CfgVerdict::kAccept);
  // status PDU "no error" ([RS4 manual §6.2, §6.3]: 05 81 00 00 00), Ext_Diag off
  EXPECT_EQ(rig.control.diagnosis, (std::vector<std::uint8_t>{0x05, 0x81, 0x00, 0x00, 0x00}));
  EXPECT_FALSE(rig.control.ext_diag);
}

TEST(GsdMatch, GsdBlockForAnotherAddressIsRefusedWith66) {
  const auto c = configure(505);  // the device is at 4 → only 504 is accepted
  Rig rig;
  rig.adapter.power_on(rig.now);
  rig.advance(3s);
  EXPECT_EQ(rig.adapter.check_parameters(from_gsd(c), rig.now), dp::slave::PrmVerdict::kPrmFault);
  // [RS4 manual §6.2, §6.3]: 05 81 00 00 42 = wrong F_Dest_Add (66)
  EXPECT_EQ(rig.control.diagnosis, (std::vector<std::uint8_t>{0x05, 0x81, 0x00, 0x00, 66}));
  EXPECT_TRUE(rig.control.ext_diag);
  EXPECT_EQ(rig.adapter.led(), LedState::kSlowBlink);
}

}  // namespace
}  // namespace rs4sim::rs4::adapter::testing
