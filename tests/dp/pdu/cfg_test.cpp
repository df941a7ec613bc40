// Chk_Cfg / Get_Cfg identifiers, [IEC 61158-6-3 Chk_Cfg/Get_Cfg] (examples from
// [CP 5613/5614 DP manual p. 204], [WAGO 750-833 GSD B756_P33.GSD], the
// [docs/references.md#dp-worked-example] worked example and the mock GSD).
#include "dp/pdu/cfg.h"

#include "pdu_test_util.h"

namespace rs4sim::dp::pdu {
namespace {

using testing::Bytes;
using testing::error_of;

Result<void> enc(const CfgIdentifier& id, fdl::DataUnit& out) {
  return encode_cfg_identifier(id, out);
}

CfgIdentifier parse_one(const Bytes& du, CfgService s = CfgService::kChkCfg) {
  const auto r = decode_cfg_identifier(du, s);
  EXPECT_TRUE(r) << (r ? "" : r.error().message());
  EXPECT_EQ(r ? r.value().size : 0U, du.size());
  return r ? r.value().identifier : CfgIdentifier{};
}

TEST(PduCfg, WorkedExampleOneByteInOneByteOut) {
  const Bytes du = {
      0x10,  // 0 general: bits 5..4 = 01 input, length 1 byte
      0x20,  // 1 general: bits 5..4 = 10 output, length 1 byte
  };
  const auto s = summarize_cfg(du, CfgService::kChkCfg);
  ASSERT_TRUE(s);
  EXPECT_EQ(s.value(), (CfgSummary{2, 1, 1}));
  EXPECT_EQ(testing::encoded(enc, general_input(1)), Bytes{0x10});
  EXPECT_EQ(testing::encoded(enc, general_output(1)), Bytes{0x20});
}

TEST(PduCfg, GeneralFormatAllFields) {
  // 0xFF: consistent (b7), words (b6), input+output (b5..4 = 11), 16 units (b3..0 = 15).
  const CfgIdentifier id = parse_one({0xFF});
  EXPECT_EQ(id.format, CfgFormat::kGeneral);
  ASSERT_TRUE(id.input && id.output);
  EXPECT_EQ(*id.input, (IoLength{16, true, true}));
  EXPECT_EQ(id.input_bytes(), 32U);
  EXPECT_EQ(id.output_bytes(), 32U);
  EXPECT_EQ(testing::encoded(enc, general_input_output(16, true, true)), Bytes{0xFF});
  // Mock GSD "0x30,0xFF": 1 byte each way + 16 words each way.
  const Bytes mock = {0x30, 0xFF};
  EXPECT_EQ(summarize_cfg(mock, CfgService::kGetCfg).value(), (CfgSummary{2, 33, 33}));
}

TEST(PduCfg, SpecialFormatCp5613Example) {
  const Bytes du = {
      0xC3,  // 0 special: b7..6 = 11 output then input length byte, 3 manufacturer bytes
      0xCF,  // 1 output: consistent, words, 16 words
      0xC7,  // 2 input: consistent, words, 8 words
      0x01, 0x02, 0x03,  // 3..5 manufacturer data
  };
  const CfgIdentifier id = parse_one(du);
  EXPECT_EQ(id.format, CfgFormat::kSpecial);
  EXPECT_EQ(*id.output, (IoLength{16, true, true}));
  EXPECT_EQ(*id.input, (IoLength{8, true, true}));
  EXPECT_EQ(id.output_bytes(), 32U);
  EXPECT_EQ(id.input_bytes(), 16U);
  EXPECT_EQ(id.manufacturer_data.size(), 3U);
  EXPECT_EQ(id.encoded_size(), 6U);
  EXPECT_EQ(testing::encoded(enc, id), du);
}

TEST(PduCfg, SpecialFormatProfisafeModule) {
  const Bytes du = {
      0xC4,                    // 0 special, out+in length bytes, 4 manufacturer bytes
      0x84,                    // 1 output: consistent, bytes, 5
      0x84,                    // 2 input: consistent, bytes, 5
      0x05, 0x0A, 0x05, 0x0A,  // 3..6 manufacturer data
  };
  const auto s = summarize_cfg(du, CfgService::kGetCfg);
  ASSERT_TRUE(s);
  EXPECT_EQ(s.value(), (CfgSummary{1, 5, 5}));
  EXPECT_EQ(testing::encoded(enc, parse_one(du)), du);
}

TEST(PduCfg, EmptySlotInputOnlyAndSkipCheck) {
  const CfgIdentifier empty = parse_one({0x00});  // free place
  EXPECT_EQ(empty, empty_slot());
  EXPECT_EQ(empty.input_bytes() + empty.output_bytes(), 0U);
  EXPECT_EQ(testing::encoded(enc, empty_slot()), Bytes{0x00});
  const CfgIdentifier in = parse_one({0x40, 0x3F});  // one input length byte: 64 bytes
  EXPECT_EQ(in.input_bytes(), 64U);
  EXPECT_FALSE(in.output);
  // Code 15 in Chk_Cfg: no manufacturer bytes follow, skip the check.
  const CfgIdentifier skip = parse_one({0x8F, 0x00});
  EXPECT_TRUE(skip.skip_manufacturer_check);
  EXPECT_EQ(skip.output_bytes(), 1U);
  EXPECT_EQ(testing::encoded(enc, skip), (Bytes{0x8F, 0x00}));
}

TEST(PduCfg, MalformedIdentifiers) {
  const auto err = [](const Bytes& du, CfgService s) {
    return error_of(decode_cfg_identifier(du, s));
  };
  EXPECT_EQ(err({}, CfgService::kChkCfg), PduError::kTooShort);
  EXPECT_EQ(err({0x40}, CfgService::kChkCfg), PduError::kTooShort);  // input length byte missing
  EXPECT_EQ(err({0xC2, 0x84}, CfgService::kChkCfg),
            PduError::kTooShort);  // input length byte missing
  EXPECT_EQ(err({0x03, 0x01}, CfgService::kChkCfg),
            PduError::kTooShort);  // 3 manufacturer bytes, 1 present
  EXPECT_EQ(err({0x0F}, CfgService::kGetCfg),
            PduError::kBadIdentifier);  // 15 not allowed in Get_Cfg
  EXPECT_EQ(error_of(summarize_cfg({}, CfgService::kChkCfg)), PduError::kTooShort);
  EXPECT_TRUE(summarize_cfg({}, CfgService::kGetCfg));
  const Bytes big(245, 0x10);
  EXPECT_EQ(error_of(summarize_cfg(big, CfgService::kChkCfg)), PduError::kTooLong);
  const Bytes trailing = {0x10, 0xC4, 0x84};
  EXPECT_EQ(error_of(summarize_cfg(trailing, CfgService::kChkCfg)), PduError::kTooShort);
}

TEST(PduCfg, EncoderRejectsUnrepresentableIdentifiers) {
  fdl::DataUnit out;
  CfgIdentifier id = general_input(17);
  EXPECT_EQ(error_of(encode_cfg_identifier(id, out)), PduError::kBadIdentifier);
  id = general_input(0);
  EXPECT_EQ(error_of(encode_cfg_identifier(id, out)), PduError::kBadIdentifier);
  id = general_input(2);
  id.output = IoLength{3, false, false};  // general format has one length for both
  EXPECT_EQ(error_of(encode_cfg_identifier(id, out)), PduError::kBadIdentifier);
  CfgIdentifier none;  // general with no I/O is the special 0x00, not general
  EXPECT_EQ(error_of(encode_cfg_identifier(none, out)), PduError::kBadIdentifier);
  CfgIdentifier sp = empty_slot();
  sp.input = IoLength{65, false, false};
  EXPECT_EQ(error_of(encode_cfg_identifier(sp, out)), PduError::kBadIdentifier);
  sp = empty_slot();
  sp.skip_manufacturer_check = true;
  sp.manufacturer_data.push_back(1);
  EXPECT_EQ(error_of(encode_cfg_identifier(sp, out)), PduError::kBadIdentifier);
  EXPECT_TRUE(out.empty());
}

}  // namespace
}  // namespace rs4sim::dp::pdu
