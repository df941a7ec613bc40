// Slave_Diag station-status bits, diag flag (DH) and extended diagnosis
// ([IEC 61158-6-3 Slave_Diag, Data_Exchange]).
#include "dp/slave/slave_error.h"
#include "tests/dp/slave/slave_harness.h"

namespace rs4sim::dp::testing {
using namespace ::rs4sim::dp::slave;  // the slave under test
namespace {

// Bits the slave never sets (master-only, [IEC 61158-6-3 Slave_Diag]): Station_Non_Existent (S1
// bit 0), Invalid_Slave_Response (S1 bit 5), Master_Lock (S1 bit 7), Deactivated (S2 bit 7).
void expect_no_master_bits(const Bytes& d) {
  ASSERT_GE(d.size(), 6U);
  EXPECT_EQ(d[0] & 0xA1, 0) << "master-only bit in Station_Status_1";
  EXPECT_EQ(d[1] & 0x80, 0) << "Deactivated set by the slave";
  EXPECT_EQ(d[1] & 0x04, 0x04) << "Station_Status_2 bit 2 must be 1";
}

TEST(SlaveDiag, MasterOnlyBitsNeverSetInAnyState) {
  SlaveHarness h;
  expect_no_master_bits(h.diag());
  EXPECT_EQ(h.send(h.dp(0x3D, SlaveHarness::example_prm())), kSc);
  expect_no_master_bits(h.diag());
  EXPECT_EQ(h.send(h.dp(0x3E, {0x10, 0x20})), kSc);
  expect_no_master_bits(h.diag());
  // Another master reads: Master_Add 2 ≠ 3, still no Master_Lock from the slave.
  const Bytes r = h.send(sd2({0x85, 0x83, 0x6D, 0x3C, 0x3E}));
  EXPECT_EQ(r, sd2({0x83, 0x85, 0x08, 0x3E, 0x3C, 0x00, 0x0C, 0x00, 0x02, 0x12, 0x34}));
}

TEST(SlaveDiag, DiagFlagUntilTheOwnerFetches) {
  SlaveHarness h;
  h.to_data_exchange();
  EXPECT_EQ(h.send(h.dx({0x01}))[6], 0x08);              // DL
  const Bytes status_pdu{0x05, 0x81, 0x00, 0x00, 0x42};  // RS4 PROFIsafe status PDU, error 66
  ASSERT_FALSE(h.app.control->set_device_diagnosis(status_pdu, true, false));
  EXPECT_EQ(h.send(h.dx({0x01}))[6], 0x0A);  // DH
  EXPECT_EQ(h.send(h.dx({0x01}))[6], 0x0A);  // still DH: not fetched
  // Another master's read does not clear the owner's flag.
  EXPECT_EQ(h.send(sd2({0x85, 0x83, 0x6D, 0x3C, 0x3E})).size(), 22U);
  EXPECT_TRUE(h.slave.diag_flag());
  EXPECT_EQ(h.diag(), (Bytes{0x08,  // Ext_Diag
                             0x0C, 0x00, 0x02, 0x12, 0x34, 0x05, 0x81, 0x00, 0x00,
                             0x42}));        // bytes 7..11 ([RS4 manual §6.2, §6.3])
  EXPECT_EQ(h.send(h.dx({0x01}))[6], 0x08);  // fetched → DL
  // Setting the same diagnosis again is no news.
  ASSERT_FALSE(h.app.control->set_device_diagnosis(status_pdu, true, false));
  EXPECT_FALSE(h.slave.diag_flag());
}

TEST(SlaveDiag, StatDiagKeepsTheFlagSet) {
  SlaveHarness h;
  h.to_data_exchange();
  ASSERT_FALSE(h.app.control->set_device_diagnosis({}, false, true));
  EXPECT_EQ(h.diag()[1], 0x0E);              // Stat_Diag + WD_On + bit 2
  EXPECT_EQ(h.send(h.dx({0x01}))[6], 0x0A);  // DH although fetched
  ASSERT_FALSE(h.app.control->set_device_diagnosis({}, false, false));
  h.diag();
  EXPECT_EQ(h.send(h.dx({0x01}))[6], 0x08);
}

TEST(SlaveDiag, InputlessSlaveAnswersScOrSd1DataHigh) {
  SlaveHarness h;
  h.app.config = {0x20};  // 1 byte out, no inputs
  h.to_data_exchange(SlaveHarness::example_prm(), {0x20});
  EXPECT_EQ(h.send(h.dx({0x01})), kSc);
  ASSERT_FALSE(h.app.control->set_device_diagnosis(Bytes{0x02, 0x01}, true, false));
  EXPECT_EQ(h.send(h.dx({0x01})), (Bytes{0x10, 0x02, 0x05, 0x0A, 0x11, 0x16}));  // SD1 FC DH
}

TEST(SlaveDiag, OverflowDropsWholeBlocksAndSetsTheBit) {
  Config cfg = example_config();
  cfg.max_diag_length = 12;  // 6 standard + 6 bytes
  SlaveHarness h(cfg);
  const Bytes blocks{0x04, 0x01, 0x02, 0x03,  // device block, 4 bytes
                     0x43, 0x00, 0x01};       // identifier block, 3 bytes → does not fit
  ASSERT_FALSE(h.app.control->set_device_diagnosis(blocks, true, false));
  EXPECT_EQ(h.diag(), (Bytes{0x0A, 0x05,
                             0x80,  // Ext_Diag_Overflow
                             0xFF, 0x12, 0x34, 0x04, 0x01, 0x02, 0x03}));
}

TEST(SlaveDiag, MalformedDeviceBlocksAreRefused) {
  SlaveHarness h;
  EXPECT_EQ(h.app.control->set_device_diagnosis(Bytes{0x05, 0x81, 0x00}, true, false),
            make_error_code(SlaveError::kInvalidDiagnosisBlock));  // header says 5, 3 present
  EXPECT_EQ(h.app.control->set_device_diagnosis(Bytes{0x00}, true, false),
            make_error_code(SlaveError::kInvalidDiagnosisBlock));  // length 0
  EXPECT_EQ(h.app.control->set_device_diagnosis(Bytes(239, 0x02), true, false),
            make_error_code(SlaveError::kDiagnosisTooLong));
  EXPECT_FALSE(h.slave.diag_flag());
}

}  // namespace
}  // namespace rs4sim::dp::testing
