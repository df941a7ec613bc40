// Global_Control ([IEC 61158-6-3 Global_Control]), Set_Slave_Add
// ([IEC 61158-6-3 Set_Slave_Add, Rd_Inp/Rd_Outp]), empty requests and I/O images
// ([IEC 61158-6-3 SAP assignment, Set_Slave_Add, Rd_Inp/Rd_Outp]) of [IEC 61158-4-3]
// [IEC 61158-6-3].
#include "dp/pdu/global_control.h"
#include "dp/pdu/sap.h"
#include "dp/pdu/set_slave_add.h"
#include "dp/pdu/simple_services.h"
#include "pdu_test_util.h"

namespace rs4sim::dp::pdu {
namespace {

using testing::Bytes;
using testing::error_of;

Result<void> enc_gc(const GlobalControl& g, fdl::DataUnit& out) {
  return encode_global_control(g, out);
}
Result<void> enc_ssa(const SetSlaveAdd& s, fdl::DataUnit& out) {
  return encode_set_slave_add(s, out);
}

TEST(PduGlobalControl, ClearFromTheWorkedExample) {
  const Bytes du = {
      0x02,  // 0 Control_Command: Clear_Data (b1)
      0x00,  // 1 Group_Select 0 = all slaves
  };
  const auto r = decode_global_control(du);
  ASSERT_TRUE(r);
  EXPECT_TRUE(r.value().clear_data);
  EXPECT_FALSE(r.value().sync || r.value().freeze || r.value().unsync || r.value().unfreeze);
  EXPECT_TRUE(r.value().addresses(0x00));
  EXPECT_TRUE(r.value().addresses(0x80));
  EXPECT_EQ(testing::encoded(enc_gc, r.value()), du);
}

TEST(PduGlobalControl, EveryCommandBitAndGroups) {
  EXPECT_TRUE(decode_global_control(Bytes{0x04, 0}).value().unfreeze);
  EXPECT_TRUE(decode_global_control(Bytes{0x08, 0}).value().freeze);
  EXPECT_TRUE(decode_global_control(Bytes{0x10, 0}).value().unsync);
  EXPECT_TRUE(decode_global_control(Bytes{0x20, 0}).value().sync);
  const GlobalControl reserved = decode_global_control(Bytes{0xC1, 0}).value();
  EXPECT_EQ(reserved.reserved, 0xC1);
  EXPECT_EQ(reserved.control_command(), 0xC1);
  GlobalControl sync_group1;
  sync_group1.sync = true;
  sync_group1.group_select = 0x01;  // group 1
  EXPECT_EQ(testing::encoded(enc_gc, sync_group1), (Bytes{0x20, 0x01}));
  EXPECT_TRUE(sync_group1.addresses(0x03));
  EXPECT_FALSE(sync_group1.addresses(0x02));
  EXPECT_FALSE(sync_group1.addresses(0x00));
}

TEST(PduGlobalControl, LengthErrors) {
  EXPECT_EQ(error_of(decode_global_control(Bytes{0x02})), PduError::kTooShort);
  EXPECT_EQ(error_of(decode_global_control(Bytes{0x02, 0x00, 0x00})), PduError::kTooLong);
}

TEST(PduSetSlaveAdd, Layout) {
  const Bytes du = {
      0x07,        // 0 New_Slave_Add 7
      0x12, 0x34,  // 1,2 Ident_Number
      0xFF,        // 3 No_Add_Chg = TRUE
      0xAB,        // 4 Rem_Slave_Data
  };
  const auto r = decode_set_slave_add(du);
  ASSERT_TRUE(r);
  EXPECT_EQ(r.value().new_address, 7);
  EXPECT_EQ(r.value().ident_number, 0x1234);
  EXPECT_TRUE(r.value().no_add_chg);
  EXPECT_EQ(r.value().rem_slave_data.size(), 1U);
  EXPECT_EQ(testing::encoded(enc_ssa, r.value()), du);
  EXPECT_FALSE(decode_set_slave_add(Bytes{0x07, 0x12, 0x34, 0x00}).value().no_add_chg);
}

TEST(PduSetSlaveAdd, Errors) {
  EXPECT_EQ(error_of(decode_set_slave_add(Bytes{0x07, 0x12, 0x34})), PduError::kTooShort);
  EXPECT_EQ(error_of(decode_set_slave_add(Bytes{sap::kDefaultSlaveAddress, 0x12, 0x34, 0})),
            PduError::kValueOutOfRange);  // 126 is only the delivery address
  EXPECT_TRUE(decode_set_slave_add(Bytes{sap::kMaxSlaveAddress, 0x12, 0x34, 0}));
  Bytes big(243, 0);
  EXPECT_EQ(error_of(decode_set_slave_add(big)), PduError::kTooLong);
  SetSlaveAdd s;
  s.new_address = 127;
  fdl::DataUnit out;
  EXPECT_EQ(error_of(encode_set_slave_add(s, out)), PduError::kValueOutOfRange);
}

TEST(PduSimpleServices, EmptyRequestsAndImages) {
  EXPECT_TRUE(decode_empty_request({}));
  EXPECT_EQ(error_of(decode_empty_request(Bytes{0x00})), PduError::kNotEmpty);
  const Bytes image = {0x3C};
  fdl::DataUnit out;
  ASSERT_TRUE(encode_io_image(image, out));
  EXPECT_EQ(testing::to_bytes(out), image);
  EXPECT_EQ(decode_io_image(image).value().size(), 1U);
  const Bytes big(245, 0);
  EXPECT_EQ(error_of(decode_io_image(big)), PduError::kTooLong);
  EXPECT_EQ(error_of(encode_io_image(big, out)), PduError::kTooLong);
}

TEST(PduSap, NumbersFromTheSpec) {
  EXPECT_EQ(sap::kSetPrm, 0x3D);
  EXPECT_EQ(sap::kChkCfg, 0x3E);
  EXPECT_EQ(sap::kSlaveDiag, 0x3C);
  EXPECT_EQ(sap::kGetCfg, 0x3B);
  EXPECT_EQ(sap::kGlobalControl, 0x3A);
  EXPECT_EQ(sap::kRdOutp, 0x39);
  EXPECT_EQ(sap::kRdInp, 0x38);
  EXPECT_EQ(sap::kSetSlaveAdd, 0x37);
  EXPECT_EQ(sap::kMsacC1, 0x33);
  EXPECT_EQ(sap::kMsacC2Rm, 0x31);
  const std::error_code ec = PduError::kBadIdentifier;
  EXPECT_STREQ(ec.category().name(), "dp.pdu");
  EXPECT_EQ(ec.message(), "malformed configuration identifier");
}

}  // namespace
}  // namespace rs4sim::dp::pdu
