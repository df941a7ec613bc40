// RS4 F-parameter diagnosis ([RS4 manual §6.3], table 6.3-1; [RS4 manual §6.2, §6.3]): every error
// number with the block that provokes it and the 5-byte status PDU the slave reports.
#include "rs4/safety/diagnosis.h"

#include "profisafe/f_device.h"
#include "profisafe/f_parameters.h"
#include "rs4/safety/profile.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

namespace rs4sim::rs4::safety {
namespace {

using profisafe::CrcLength;
using profisafe::encode_f_parameters;
using profisafe::FParameters;
using profisafe::Sil;
using profisafe::validate;

using Bytes = std::vector<std::uint8_t>;

// Status PDU after the 6 standard diagnosis bytes (bytes 7..11).
Bytes status_bytes(std::uint8_t nn) {
  return {
      0x05,  // byte 7: length of the status PDU = 5 incl. header
      0x81,  // byte 8: type status message
      0x00,  // byte 9: no slots
      0x00,  // byte 10: no status differentiation
      nn,    // byte 11: error number
  };
}

Bytes to_bytes(const std::array<std::uint8_t, 5>& a) { return {a.begin(), a.end()}; }

// A block with fields changed from the RS4 defaults at address 4, CRC1 computed in, so only
// the named field is wrong. The fixed blocks below carry CRC1 values computed by an
// independent bitwise implementation of the VERIFIED rule ([IEC 61784-3-3 CRC1]).
Bytes block(void (*change)(FParameters&)) {
  FParameters p;
  change(p);
  const auto b = encode_f_parameters(p);
  return {b.begin(), b.end()};
}

void expect_code(const Bytes& b, FDiagnosis d, std::uint8_t nn) {
  const auto v = validate(b, device_profile(4));
  EXPECT_EQ(diagnosis(v.fault), d);
  EXPECT_EQ(static_cast<int>(diagnosis(v.fault)), nn);
  EXPECT_EQ(to_bytes(status_pdu(diagnosis(v.fault))), status_bytes(nn));
}

TEST(Rs4SafetyDiagnosis, Code0NoError) {
  const Bytes b{0x14, 0x00, 0x00, 0x01, 0x01, 0xF8, 0x00, 0x0A, 0x83, 0xA9};  // RS4 defaults
  expect_code(b, FDiagnosis::kNone, 0);
  EXPECT_TRUE(validate(b, device_profile(4)).ok());
}

TEST(Rs4SafetyDiagnosis, Code65InternalDestAdd) {
  // The device's own F_Dest_Add is not valid: DP address 127 is not a station address.
  const Bytes b{0x14, 0x00,   // 0 F_Prm_Flag1 SIL2 2-byte CRC, 1 F_Prm_Flag2 V1 block 0
                0x00, 0x01,   // 2 F_Source_Add 1
                0x02, 0x73,   // 4 F_Dest_Add 627 = 500 + 127
                0x00, 0x0A,   // 6 F_WD_Time 10
                0x13, 0x28};  // 8 F_Par_CRC (correct)
  const auto v = validate(b, device_profile(127));
  EXPECT_EQ(static_cast<int>(diagnosis(v.fault)), 65);
  EXPECT_EQ(to_bytes(status_pdu(diagnosis(v.fault))), status_bytes(65));
}

TEST(Rs4SafetyDiagnosis, Code66WrongDestAdd) {
  const Bytes b{0x14, 0x00, 0x00, 0x01,
                0x01, 0xF9,  // 4 F_Dest_Add = 505 but the device is at address 4 (expects 504)
                0x00, 0x0A, 0x63, 0x81};  // 8 F_Par_CRC (correct)
  expect_code(b, FDiagnosis::kWrongDestAdd, 66);
  // 500 + address: at address 5 the same block is accepted
  EXPECT_TRUE(validate(block([](FParameters& p) { p.dest_add = 505; }), device_profile(5)).ok());
}

TEST(Rs4SafetyDiagnosis, Code67WrongSourceAdd) {
  const Bytes b{0x14, 0x00, 0x00, 0x00,               // 2 F_Source_Add = 0: not a valid address
                0x01, 0xF8, 0x00, 0x0A, 0x4C, 0x79};  // 8 F_Par_CRC (correct)
  expect_code(b, FDiagnosis::kWrongSourceAdd, 67);
  expect_code(block([](FParameters& p) { p.source_add = 0; }), FDiagnosis::kWrongSourceAdd, 67);
  expect_code(block([](FParameters& p) { p.source_add = 65535; }), FDiagnosis::kWrongSourceAdd, 67);
  EXPECT_TRUE(
      validate(block([](FParameters& p) { p.source_add = 65534; }), device_profile(4)).ok());
}

TEST(Rs4SafetyDiagnosis, Code68WrongWdTime) {
  const Bytes b{0x14, 0x00, 0x00, 0x01, 0x01, 0xF8, 0x00, 0x09,  // 6 F_WD_Time = 9 ms < 10 ms
                0x50, 0x54};                                     // 8 F_Par_CRC (correct)
  expect_code(b, FDiagnosis::kWrongWdTime, 68);
  expect_code(block([](FParameters& p) { p.wd_time_ms = 9; }), FDiagnosis::kWrongWdTime, 68);
  expect_code(block([](FParameters& p) { p.wd_time_ms = 1001; }), FDiagnosis::kWrongWdTime, 68);
  expect_code(block([](FParameters& p) { p.wd_time_ms = 0; }), FDiagnosis::kWrongWdTime, 68);
  EXPECT_TRUE(validate(block([](FParameters& p) { p.wd_time_ms = 1000; }), device_profile(4)).ok());
}

TEST(Rs4SafetyDiagnosis, Code69WrongSil) {
  const Bytes b{0x18,  // 0 F_Prm_Flag1: F_SIL = 2 (SIL3), F_CRC_Length 1
                0x00, 0x00, 0x01, 0x01, 0xF8, 0x00, 0x0A, 0xEE, 0xD3};  // 8 F_Par_CRC (correct)
  EXPECT_EQ(block([](FParameters& p) { p.sil = Sil::kSil3; }), b);
  expect_code(b, FDiagnosis::kWrongSil, 69);
  expect_code(block([](FParameters& p) { p.sil = Sil::kSil1; }), FDiagnosis::kWrongSil, 69);
}

TEST(Rs4SafetyDiagnosis, Code70WrongCrcLength) {
  const Bytes b{0x04,  // 0 F_Prm_Flag1: SIL2, F_CRC_Length = 0 (3-byte CRC, a V2 setting)
                0x00, 0x00, 0x01, 0x01, 0xF8, 0x00, 0x0A, 0xD5, 0x68};  // 8 F_Par_CRC (correct)
  EXPECT_EQ(block([](FParameters& p) { p.crc_length = CrcLength::k3Byte; }), b);
  expect_code(b, FDiagnosis::kWrongCrcLength, 70);
  expect_code(block([](FParameters& p) { p.crc_length = CrcLength::kReserved; }),
              FDiagnosis::kWrongCrcLength, 70);
}

TEST(Rs4SafetyDiagnosis, Code71WrongBlockIdOrParVersion) {
  const Bytes v2{0x14,
                 0x40,  // 1 F_Prm_Flag2: F_Par_Version = 1 (V2)
                 0x00, 0x01, 0x01, 0xF8, 0x00, 0x0A, 0x6D, 0xA8};  // 8 F_Par_CRC (correct)
  EXPECT_EQ(block([](FParameters& p) { p.par_version = 1; }), v2);
  expect_code(v2, FDiagnosis::kWrongBlockIdOrParVersion, 71);
  const Bytes id = block([](FParameters& p) { p.block_id = 1; });
  EXPECT_EQ(id[1], 0x08);  // offset 1: F_Block_ID = 1
  expect_code(id, FDiagnosis::kWrongBlockIdOrParVersion, 71);
  expect_code(block([](FParameters& p) { p.check_ipar = true; }),
              FDiagnosis::kWrongBlockIdOrParVersion, 71);
  // A block that does not parse (reserved bit, wrong size) is not a layout the RS4 knows.
  Bytes reserved = block([](FParameters&) {});
  reserved[1] = 0x01;
  expect_code(reserved, FDiagnosis::kWrongBlockIdOrParVersion, 71);
  expect_code(Bytes(9, 0), FDiagnosis::kWrongBlockIdOrParVersion, 71);
}

TEST(Rs4SafetyDiagnosis, Code72WrongCrc1ReportsBothValues) {
  Bytes b{0x14, 0x00, 0x00, 0x01, 0x01,
          0xF8, 0x00, 0x0A, 0x83, 0xA8};  // 8 F_Par_CRC = 0x83A8, one off the correct 0x83A9
  expect_code(b, FDiagnosis::kWrongCrc1, 72);
  const auto v = validate(b, device_profile(4));
  EXPECT_EQ(v.received_crc1, 0x83A8);
  EXPECT_EQ(v.computed_crc1, 0x83A9);
}

TEST(Rs4SafetyDiagnosis, FirstFailingCheckInCodeOrderWins) {
  // wrong F_Dest_Add (66) and wrong SIL (69) and wrong CRC1 (72): 66 is reported.
  FParameters p;
  p.dest_add = 600;
  p.sil = Sil::kSil3;
  p.par_crc = 0;
  EXPECT_EQ(diagnosis(validate(p, device_profile(4)).fault), FDiagnosis::kWrongDestAdd);
}

TEST(Rs4SafetyDiagnosis, ErrorCodesHaveMessages) {
  const std::error_code d = FDiagnosis::kWrongCrc1;
  EXPECT_EQ(d.value(), 72);
  EXPECT_EQ(d.message(), "72 wrong CRC1 over the F-parameters");
}

TEST(Rs4SafetyDiagnosis, FDeviceRefusingParametersReportsTheStatusPdu) {
  profisafe::FDevice dev(profisafe::FDeviceConfig{device_profile(4), 1, {}});
  FParameters p;
  p.dest_add = 505;
  const auto v = dev.set_parameters(encode_f_parameters(p));
  EXPECT_EQ(diagnosis(v.fault), FDiagnosis::kWrongDestAdd);
  EXPECT_EQ(status_pdu(diagnosis(dev.last_validation().fault)),
            (std::array<std::uint8_t, 5>{0x05, 0x81, 0x00, 0x00, 66}));
}

TEST(Rs4SafetyDiagnosis, Rs4ProfileDestAddIs500PlusAddress) {
  EXPECT_EQ(device_profile(0).dest_add, 500);
  EXPECT_EQ(device_profile(4).dest_add, 504);
  EXPECT_EQ(device_profile(126).dest_add, 626);
  EXPECT_EQ(device_profile(127).dest_add, 0);
  EXPECT_EQ(f_dest_add(7), 507);
}

}  // namespace
}  // namespace rs4sim::rs4::safety
