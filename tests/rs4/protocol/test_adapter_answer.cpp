// READ answers of the adapter commands ([RS4 manual §5.2.2, tables 5.2-6],
// 5.2-7, 5.2-8) and the error ring buffer.
#include "rs4/protocol/adapter_answer.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace rs4sim::rs4::protocol {
namespace {

using Bytes = std::vector<std::uint8_t>;

TEST(Rs4AdapterAnswer, VersionAnswerAsTable5_2_6) {
  VersionAnswer v;
  v.main_interface = 3;
  v.function = 2;
  v.bugfix = 1;
  const Bytes expected{
      0x90,  // 5: answer to PROFI_CMD_GET_VERSION
      0x01,  // 6: PROFIsafe version high = 1
      0x00,  // 7: PROFIsafe version low = 0
      0x01,  // 8: PROFIBUS DP version high = 1
      0x00,  // 9: PROFIBUS DP version low = 0
      0x11,  // 10: DPV1SL components high: C2 (0x01) + DPC31 (0x10)
      0x0D,  // 11: DPV1SL components low: C2 (0x01) + SUB_AL (0x04) + SUB_CH1 (0x08)
      0x03,  // 12: DPV1SL main interface
      0x02,  // 13: DPV1SL function
      0x01,  // 14: DPV1SL bugfix
  };
  EXPECT_EQ(encode_version_answer(v), expected);
  auto d = decode_version_answer(expected);
  ASSERT_TRUE(d);
  EXPECT_EQ(d.value(), v);
  EXPECT_EQ(decode_version_answer(Bytes(expected.begin(), expected.end() - 1)).error(),
            ProtocolError::kBadAnswerLength);
  EXPECT_EQ(decode_version_answer(Bytes{0x84, 1, 0, 1, 0, 0x11, 0x0D, 0, 0, 0}).error(),
            ProtocolError::kBadAnswerCode);
}

TEST(Rs4AdapterAnswer, LastErrorAnswerAllValuesHighByteFirst) {
  const LastErrorAnswer a{0x2A0B, 0x0102, 0x2418, 0x0304};
  const Bytes expected{
      0x84,        // 5: answer to PROFI_CMD_ERROR
      0x2A, 0x0B,  // 6..7: μC2 error number hi, lo
      0x01, 0x02,  // 8..9: μC2 count hi, lo
      0x24, 0x18,  // 10..11: μC1 error number hi, lo
      0x03, 0x04,  // 12..13: μC1 count hi, lo (DECISION
                   // [docs/decisions.md#rs4-uc1-count-byte-order], the table says lo, hi)
  };
  EXPECT_EQ(encode_last_error_answer(a), expected);
  auto d = decode_last_error_answer(expected);
  ASSERT_TRUE(d);
  EXPECT_EQ(d.value(), a);
  EXPECT_EQ(decode_last_error_answer(Bytes{0x84, 0}).error(), ProtocolError::kBadAnswerLength);
}

TEST(Rs4ErrorRingBuffer, EmptyMemory) {
  const ErrorRingBuffer ring;
  EXPECT_EQ(ring.write_index, 19);  // the first push lands in slot 0
  EXPECT_EQ(ring.age_flag, 1);
  for (const auto e : ring.entries) EXPECT_EQ(e, 0);
}

TEST(Rs4ErrorRingBuffer, PushAdvancesWrapsAndResetsAge) {
  ErrorRingBuffer ring;
  ring.push(0x2A04);
  EXPECT_EQ(ring.write_index, 0);
  EXPECT_EQ(ring.entries[0], 0x2A04);
  EXPECT_EQ(ring.age_flag, 0);  // occurred in the last cycle
  ring.mark_aged();
  EXPECT_EQ(ring.age_flag, 1);
  for (std::uint16_t i = 1; i <= 20; ++i) ring.push(static_cast<std::uint16_t>(0x1000 + i));
  EXPECT_EQ(ring.write_index, 0);      // 21 pushes: wrapped once, slot 0 again
  EXPECT_EQ(ring.entries[0], 0x1014);  // overwritten by the 21st entry
  EXPECT_EQ(ring.entries[19], 0x1013);
  EXPECT_EQ(ring.newest(), 0x1014);
  EXPECT_EQ(ring.age_flag, 0);
}

TEST(Rs4AdapterAnswer, ErrorMemoryAnswerIs85BytesAsTable5_2_8) {
  ErrorMemoryAnswer a;
  a.uc2.push(0x2A0B);  // μC2 slot 0
  a.uc2.push(0x2A06);  // μC2 slot 1, newest
  a.uc1.push(0x2418);  // μC1 slot 0
  a.uc1.mark_aged();
  const Bytes bytes = encode_error_memory_answer(a);
  ASSERT_EQ(bytes.size(), 85U);
  EXPECT_EQ(bytes[0], 0x91);   // 5: answer to PROFI_CMD_GET_ERROR
  EXPECT_EQ(bytes[1], 1);      // 6: μC2 write index of the newest entry
  EXPECT_EQ(bytes[2], 0);      // 7: μC2 age: 0 = occurred in the last cycle
  EXPECT_EQ(bytes[3], 0x2A);   // 8: μC2 index 0 high
  EXPECT_EQ(bytes[4], 0x0B);   // 9: μC2 index 0 low
  EXPECT_EQ(bytes[5], 0x2A);   // 10: μC2 index 1 high
  EXPECT_EQ(bytes[6], 0x06);   // 11: μC2 index 1 low
  EXPECT_EQ(bytes[41], 0x00);  // 46: μC2 index 19 high
  EXPECT_EQ(bytes[42], 0x00);  // 47: μC2 index 19 low
  EXPECT_EQ(bytes[43], 0);     // 48: μC1 write index
  EXPECT_EQ(bytes[44], 1);     // 49: μC1 age: 1 = older
  EXPECT_EQ(bytes[45], 0x24);  // 50: μC1 index 0 high
  EXPECT_EQ(bytes[46], 0x18);  // 51: μC1 index 0 low
  EXPECT_EQ(bytes[84], 0x00);  // 89: μC1 index 19 low
  auto d = decode_error_memory_answer(bytes);
  ASSERT_TRUE(d);
  EXPECT_EQ(d.value(), a);
}

TEST(Rs4AdapterAnswer, ErrorMemoryAnswerRejectsBadIndexAgeAndLength) {
  Bytes bytes = encode_error_memory_answer({});
  Bytes bad_index = bytes;
  bad_index[1] = 20;  // write index beyond 19
  EXPECT_EQ(decode_error_memory_answer(bad_index).error(), ProtocolError::kBadAnswerValue);
  Bytes bad_age = bytes;
  bad_age[44] = 2;  // μC1 age flag is 0 or 1
  EXPECT_EQ(decode_error_memory_answer(bad_age).error(), ProtocolError::kBadAnswerValue);
  bytes.push_back(0);
  EXPECT_EQ(decode_error_memory_answer(bytes).error(), ProtocolError::kBadAnswerLength);
}

// ProxyStationStatus.direction shows the direction the RS4 asked for in its
// PROFI_CMD_PROXY_BEGIN answer; clients compare the word.
TEST(Rs4AdapterAnswer, EverySyncDirectionHasItsApiWord) {
  EXPECT_EQ(to_token(SyncDirection::kNone), "none");
  EXPECT_EQ(to_token(SyncDirection::kVerify), "verify");
  EXPECT_EQ(to_token(SyncDirection::kUpload), "upload");
  EXPECT_EQ(to_token(SyncDirection::kDownload), "download");
  EXPECT_EQ(to_token(static_cast<SyncDirection>(4)), "?");  // the decoder refuses 4 and up
}

}  // namespace
}  // namespace rs4sim::rs4::protocol
