// Structured parameter blocks ([IEC 61158-6-3 structured Prm_Data], F-parameter block shape
// [PROFIBUS GSD spec F-parameter keywords]) and the I&M call header / I&M0 record
// ([IEC 61158-6-3 MSAC_C1]).
#include "dp/pdu/im.h"
#include "dp/pdu/prm_blocks.h"
#include "pdu_test_util.h"

namespace rs4sim::dp::pdu {
namespace {

using testing::Bytes;
using testing::error_of;

TEST(PduPrmBlocks, WagoFParameterBlockThenUserBlock) {
  const Bytes data = {
      0x0E,        // 0 Structure_Length 14 incl. itself
      0x05,        // 1 Structure_Type 5 (F-parameters, [PROFIBUS GSD spec F-parameter keywords])
      0x01,        // 2 slot 1
      0x00,        // 3 reserved/index
      0x08,        // 4 F_Prm_Flag1: F_SIL = 2 (SIL3)
      0x40,        // 5 F_Prm_Flag2: F_Par_Version 1 (V2)
      0x00, 0x01,  // 6,7 F_Source_Add 1
      0x00, 0x05,  // 8,9 F_Dest_Add 5
      0x00, 0x96,  // 10,11 F_WD_Time 150 ms
      0x03, 0x55,  // 12,13 F_Par_CRC 853
      0x05,        // 14 Structure_Length 5
      0x81,        // 15 type user parameter data
      0x02, 0x00,  // 16,17 slot 2, index 0
      0xAA,        // 18 data
  };
  PrmBlockReader reader(data);
  const auto a = reader.next();
  ASSERT_TRUE(a && a.value());
  EXPECT_EQ(a.value()->type, prm_block_type::kFParameters);
  EXPECT_EQ(a.value()->slot, 1);
  EXPECT_EQ(a.value()->data.size(), 10U);
  EXPECT_EQ(a.value()->raw.size(), 14U);
  const auto b = reader.next();
  ASSERT_TRUE(b && b.value());
  EXPECT_EQ(b.value()->type, prm_block_type::kUserPrmData);
  EXPECT_EQ(b.value()->data.size(), 1U);
  const auto end = reader.next();
  ASSERT_TRUE(end);
  EXPECT_FALSE(end.value());
  fdl::DataUnit out;
  ASSERT_TRUE(encode_prm_block(0x05, 1, 0, a.value()->data, out));
  ASSERT_TRUE(encode_prm_block(0x81, 2, 0, b.value()->data, out));
  EXPECT_EQ(testing::to_bytes(out), data);
}

TEST(PduPrmBlocks, MalformedLengths) {
  const auto first = [](const Bytes& d) {
    PrmBlockReader r(d);
    const auto x = r.next();
    const auto after = r.next();
    EXPECT_TRUE(after && !after.value());  // stops after an error
    return error_of(x);
  };
  EXPECT_EQ(first({0x03, 0x05, 0x01}), PduError::kBadPrmBlock);        // length < 4
  EXPECT_EQ(first({0x0E, 0x05, 0x01, 0x00}), PduError::kBadPrmBlock);  // 14 > 4 present
  EXPECT_EQ(first({0x00}), PduError::kBadPrmBlock);
  fdl::DataUnit out;
  const Bytes big(252, 0);
  EXPECT_EQ(error_of(encode_prm_block(0x81, 0, 0, big, out)), PduError::kValueOutOfRange);
}

TEST(PduIm, CallHeaderForIm0) {
  const Bytes data = {
      0x08,        // 0 Extended_Function_Num: I&M call
      0x00,        // 1 reserved
      0xFD, 0xE8,  // 2,3 I&M index 65000 = I&M0
  };
  const auto r = decode_im_call(data);
  ASSERT_TRUE(r);
  EXPECT_EQ(r.value().header, (ImCallHeader{0x08, 0, kIm0Index}));
  EXPECT_TRUE(r.value().record.empty());
  fdl::DataUnit out;
  ASSERT_TRUE(encode_im_call(r.value().header, out));
  EXPECT_EQ(testing::to_bytes(out), data);
  EXPECT_EQ(error_of(decode_im_call(Bytes{0x08, 0x00, 0xFD})), PduError::kTooShort);
}

TEST(PduIm, Im0RecordOffsets) {
  Bytes rec(64, 0);
  rec[10] = 0x01;
  rec[11] = 0x2C;                                          // 10,11 MANUFACTURER_ID 0x012C
  for (std::size_t i = 0; i < 20; ++i) rec[12 + i] = ' ';  // 12..31 ORDER_ID
  rec[12] = 'R';
  rec[13] = 'S';
  rec[14] = '4';
  for (std::size_t i = 0; i < 16; ++i)
    rec[32 + i] = static_cast<std::uint8_t>('0' + i % 10);  // 32..47 SERIAL_NUMBER
  rec[48] = 0x00;
  rec[49] = 0x02;  // 48,49 HARDWARE_REVISION 2
  rec[50] = 'V';
  rec[51] = 1;
  rec[52] = 2;
  rec[53] = 3;  // 50..53 SOFTWARE_REVISION V1.2.3
  rec[54] = 0x00;
  rec[55] = 0x07;  // 54,55 REVISION_COUNTER 7
  rec[56] = 0x3A;
  rec[57] = 0x00;  // 56,57 PROFILE_ID 0x3A00
  rec[58] = 0x00;
  rec[59] = 0x01;  // 58,59 PROFILE_SPECIFIC_TYPE 1
  rec[60] = 0x01;
  rec[61] = 0x01;  // 60,61 IM_VERSION 1.1
  rec[62] = 0x00;
  rec[63] = 0x00;  // 62,63 IM_SUPPORTED: only I&M0
  const auto r = decode_im0(rec);
  ASSERT_TRUE(r);
  const Im0& im = r.value();
  EXPECT_EQ(im.manufacturer_id, 0x012C);
  EXPECT_EQ(im.order_id[0], 'R');
  EXPECT_EQ(im.order_id[19], ' ');
  EXPECT_EQ(im.serial_number[15], '5');
  EXPECT_EQ(im.hardware_revision, 2);
  EXPECT_EQ(im.software_revision, (std::array<std::uint8_t, 4>{'V', 1, 2, 3}));
  EXPECT_EQ(im.revision_counter, 7);
  EXPECT_EQ(im.profile_id, 0x3A00);
  EXPECT_EQ(im.profile_specific_type, 1);
  EXPECT_EQ(im.im_supported, 0);
  fdl::DataUnit out;
  ASSERT_TRUE(encode_im0(im, out));
  EXPECT_EQ(testing::to_bytes(out), rec);
  EXPECT_EQ(error_of(decode_im0(Bytes(63, 0))), PduError::kTooShort);
  EXPECT_EQ(error_of(decode_im0(Bytes(65, 0))), PduError::kTooLong);
}

}  // namespace
}  // namespace rs4sim::dp::pdu
