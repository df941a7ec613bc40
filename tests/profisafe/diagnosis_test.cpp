// RS4 F-parameter diagnosis (manual §6.3, table 6.3-1; rs4-profisafe.md §8): every error
// number with the block that provokes it and the 5-byte status PDU the slave reports.
#include "profisafe/f_parameters.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

namespace rs4sim::profisafe {
namespace {

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

// A block with fields changed from the RS4 defaults at address 4; CRC1 is correct unless
// the test says otherwise, so only the named field is wrong.
Bytes block(void (*change)(FParameters&)) {
  FParameters p;
  change(p);
  const auto b = encode_f_parameters(p);
  return {b.begin(), b.end()};
}

void expect_code(const Bytes& b, FDiagnosis d, std::uint8_t nn) {
  const auto v = validate(b, DeviceProfile::rs4(4));
  EXPECT_EQ(v.diagnosis, d);
  EXPECT_EQ(static_cast<int>(v.diagnosis), nn);
  EXPECT_EQ(to_bytes(status_pdu(v.diagnosis)), status_bytes(nn));
}

TEST(ProfisafeDiagnosis, Code0NoError) {
  const Bytes b{0x14, 0x00, 0x00, 0x01, 0x01, 0xF8, 0x00, 0x0A, 0x83, 0xA9};  // RS4 defaults
  expect_code(b, FDiagnosis::kNone, 0);
  EXPECT_TRUE(validate(b, DeviceProfile::rs4(4)).ok());
}

TEST(ProfisafeDiagnosis, Code65InternalDestAdd) {
  // The device's own F_Dest_Add is not valid: DP address 127 is not a station address.
  const Bytes b = block([](FParameters& p) { p.dest_add = 627; });
  const auto v = validate(b, DeviceProfile::rs4(127));
  EXPECT_EQ(static_cast<int>(v.diagnosis), 65);
  EXPECT_EQ(to_bytes(status_pdu(v.diagnosis)), status_bytes(65));
}

TEST(ProfisafeDiagnosis, Code66WrongDestAdd) {
  // offset 4: F_Dest_Add = 505 but the device is at address 4 (expects 504)
  expect_code(block([](FParameters& p) { p.dest_add = 505; }), FDiagnosis::kWrongDestAdd, 66);
  // 500 + address: at address 5 the same block is accepted
  EXPECT_TRUE(validate(block([](FParameters& p) { p.dest_add = 505; }), DeviceProfile::rs4(5)).ok());
}

TEST(ProfisafeDiagnosis, Code67WrongSourceAdd) {
  expect_code(block([](FParameters& p) { p.source_add = 0; }), FDiagnosis::kWrongSourceAdd, 67);
  expect_code(block([](FParameters& p) { p.source_add = 65535; }), FDiagnosis::kWrongSourceAdd, 67);
  EXPECT_TRUE(validate(block([](FParameters& p) { p.source_add = 65534; }), DeviceProfile::rs4(4)).ok());
}

TEST(ProfisafeDiagnosis, Code68WrongWdTime) {
  expect_code(block([](FParameters& p) { p.wd_time_ms = 9; }), FDiagnosis::kWrongWdTime, 68);
  expect_code(block([](FParameters& p) { p.wd_time_ms = 1001; }), FDiagnosis::kWrongWdTime, 68);
  expect_code(block([](FParameters& p) { p.wd_time_ms = 0; }), FDiagnosis::kWrongWdTime, 68);
  EXPECT_TRUE(validate(block([](FParameters& p) { p.wd_time_ms = 1000; }), DeviceProfile::rs4(4)).ok());
}

TEST(ProfisafeDiagnosis, Code69WrongSil) {
  // offset 0 = 0x18: F_SIL = 2 (SIL3) with the 2-byte CRC
  const Bytes b = block([](FParameters& p) { p.sil = Sil::kSil3; });
  EXPECT_EQ(b[0], 0x18);
  expect_code(b, FDiagnosis::kWrongSil, 69);
  expect_code(block([](FParameters& p) { p.sil = Sil::kSil1; }), FDiagnosis::kWrongSil, 69);
}

TEST(ProfisafeDiagnosis, Code70WrongCrcLength) {
  // offset 0 = 0x04: F_CRC_Length = 0 (3-byte CRC, a V2 setting)
  const Bytes b = block([](FParameters& p) { p.crc_length = CrcLength::k3Byte; });
  EXPECT_EQ(b[0], 0x04);
  expect_code(b, FDiagnosis::kWrongCrcLength, 70);
  expect_code(block([](FParameters& p) { p.crc_length = CrcLength::kReserved; }), FDiagnosis::kWrongCrcLength, 70);
}

TEST(ProfisafeDiagnosis, Code71WrongBlockIdOrParVersion) {
  const Bytes v2 = block([](FParameters& p) { p.par_version = 1; });
  EXPECT_EQ(v2[1], 0x40);  // offset 1: F_Par_Version = 1
  expect_code(v2, FDiagnosis::kWrongBlockIdOrParVersion, 71);
  const Bytes id = block([](FParameters& p) { p.block_id = 1; });
  EXPECT_EQ(id[1], 0x08);  // offset 1: F_Block_ID = 1
  expect_code(id, FDiagnosis::kWrongBlockIdOrParVersion, 71);
  expect_code(block([](FParameters& p) { p.check_ipar = true; }), FDiagnosis::kWrongBlockIdOrParVersion, 71);
  // A block that does not parse (reserved bit, wrong size) is not a layout the RS4 knows.
  Bytes reserved = block([](FParameters&) {});
  reserved[1] = 0x01;
  expect_code(reserved, FDiagnosis::kWrongBlockIdOrParVersion, 71);
  expect_code(Bytes(9, 0), FDiagnosis::kWrongBlockIdOrParVersion, 71);
}

TEST(ProfisafeDiagnosis, Code72WrongCrc1ReportsBothValues) {
  Bytes b{0x14, 0x00, 0x00, 0x01, 0x01, 0xF8, 0x00, 0x0A,
          0x83, 0xA8};  // 8 F_Par_CRC = 0x83A8, one off the correct 0x83A9
  expect_code(b, FDiagnosis::kWrongCrc1, 72);
  const auto v = validate(b, DeviceProfile::rs4(4));
  EXPECT_EQ(v.received_crc1, 0x83A8);
  EXPECT_EQ(v.computed_crc1, 0x83A9);
}

TEST(ProfisafeDiagnosis, FirstFailingCheckInCodeOrderWins) {
  // wrong F_Dest_Add (66) and wrong SIL (69) and wrong CRC1 (72): 66 is reported.
  FParameters p;
  p.dest_add = 600;
  p.sil = Sil::kSil3;
  p.par_crc = 0;
  EXPECT_EQ(validate(p, DeviceProfile::rs4(4)).diagnosis, FDiagnosis::kWrongDestAdd);
}

TEST(ProfisafeDiagnosis, Rs4ProfileDestAddIs500PlusAddress) {
  EXPECT_EQ(DeviceProfile::rs4(0).dest_add, 500);
  EXPECT_EQ(DeviceProfile::rs4(4).dest_add, 504);
  EXPECT_EQ(DeviceProfile::rs4(126).dest_add, 626);
  EXPECT_EQ(DeviceProfile::rs4(127).dest_add, 0);
}

}  // namespace
}  // namespace rs4sim::profisafe
