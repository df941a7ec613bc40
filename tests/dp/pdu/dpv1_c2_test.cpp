// DPV1 MSAC_C2 PDUs, [IEC 61158-6-3 MSAC_C2] (layouts [VPC3+ dp_if.h §11.7], defaults
// [Softing PB_DP.H]).
#include "dp/pdu/dpv1_c2.h"

#include "pdu_test_util.h"

namespace rs4sim::dp::pdu {
namespace {

using testing::Bytes;
using testing::enc;
using testing::error_of;

TEST(PduDpv1C2, ResourceManagerReply) {
  const Bytes du = {
      0x56,        // 0 function resource manager
      0x30,        // 1 connection SAP 48
      0x00, 0x64,  // 2,3 Send_Timeout 100 · 10 ms = 1 s (≥ 1.5 Mbit/s default)
  };
  const auto r = decode_rm_response(du);
  ASSERT_TRUE(r);
  EXPECT_EQ(r.value(), (ResourceManagerResponse{48, 100}));
  EXPECT_EQ(enc(r.value()), du);
  EXPECT_EQ(error_of(decode_rm_response(Bytes{0x56, 0x31, 0x00, 0x64})),
            PduError::kValueOutOfRange);
  EXPECT_EQ(error_of(decode_rm_response(Bytes{0x57, 0x30, 0x00, 0x64})),
            PduError::kBadFunctionCode);
}

TEST(PduDpv1C2, InitiateRequestWithSoftingDefaults) {
  const Bytes du = {
      0x57,              // 0 Initiate
      0x00, 0x00, 0x00,  // 1..3 reserved
      0x00, 0x64,        // 4,5 Send_Timeout 100 (1 s)
      0x01, 0x00,        // 6,7 Features_Supported
      0x00, 0x00,        // 8,9 Profile_Features_Supported
      0x00, 0x00,        // 10,11 Profile_Ident_Number
      0x00, 0x02,        // 12,13 S_Type 0, S_Len 2
      0x00, 0x02,        // 14,15 D_Type 0, D_Len 2
      0x00, 0x00,        // 16,17 S_Addr: API 0, SCL 0
      0x00, 0x00,        // 18,19 D_Addr: API 0, SCL 0
  };
  const auto r = decode_c2_request(du);
  ASSERT_TRUE(r);
  const auto& req = std::get<InitiateRequest>(r.value());
  EXPECT_EQ(req.send_timeout, 100);
  EXPECT_EQ(req.features_supported, (std::array<std::uint8_t, 2>{0x01, 0x00}));
  EXPECT_EQ(req.s_addr.size(), 2U);
  EXPECT_EQ(req.d_addr.size(), 2U);
  EXPECT_EQ(enc(req), du);
}

TEST(PduDpv1C2, InitiateResponse) {
  const Bytes du = {
      0x57,        // 0 Initiate
      0xF0,        // 1 Max_Len_Data_Unit 240
      0x01, 0x00,  // 2,3 Features_Supported
      0x00, 0x00,  // 4,5 Profile_Features_Supported
      0x12, 0x34,  // 6,7 Profile_Ident_Number
      0x00, 0x02,  // 8,9 S_Type, S_Len
      0x00, 0x02,  // 10,11 D_Type, D_Len
      0x00, 0x00, 0x00, 0x00,
  };
  const auto r = decode_c2_response(du);
  ASSERT_TRUE(r);
  const auto& res = std::get<InitiateResponse>(r.value());
  EXPECT_EQ(res.max_len_data_unit, 240);
  EXPECT_EQ(res.profile_ident_number, 0x1234);
  EXPECT_EQ(enc(res), du);
}

TEST(PduDpv1C2, AbortTimeout) {
  const Bytes du = {
      0x58,  // 0 Abort
      0x00,  // 1 Subnet: none
      0x13,  // 2 b5..4 = 1 MSAC_C2, b3..0 = 3 timeout
      0x00,  // 3 reserved
  };
  const Abort a{AbortSubnet::kNone, AbortInstance::kMsacC2, abort_reason::kTimeout, 0};
  testing::expect_known_answer(decode_c2_request, du, a);
  testing::expect_known_answer(decode_c2_response, du, a);
}

TEST(PduDpv1C2, DataTransportReadWriteIdle) {
  const Bytes transport = {0x51, 0x00, 0x05, 0x02, 0xAA, 0xBB};
  EXPECT_EQ(enc(std::get<DataTransport>(decode_c2_request(transport).value())), transport);
  EXPECT_EQ(enc(std::get<DataTransport>(decode_c2_response(transport).value())), transport);
  EXPECT_EQ(std::get<ReadRequest>(decode_c2_request(Bytes{0x5E, 1, 2, 3}).value()),
            (ReadRequest{1, 2, 3}));
  EXPECT_EQ(std::get<WriteResponse>(decode_c2_response(Bytes{0x5F, 1, 2, 3}).value()),
            (WriteResponse{1, 2, 3}));
  EXPECT_EQ(enc(std::get<Idle>(decode_c2_request(Bytes{0x48}).value())), Bytes{0x48});
  EXPECT_EQ(enc(std::get<Idle>(decode_c2_request(Bytes{0x48, 0x00}).value())), (Bytes{0x48, 0x00}));
  const Dpv1Error neg =
      std::get<Dpv1Error>(decode_c2_response(Bytes{0xD7, 0x80, 0xB5, 0x00}).value());
  EXPECT_EQ(neg.function, Dpv1Function::kInitiate);
  EXPECT_EQ(neg.error_code_1, ErrorCode1::kStateConflict);
  EXPECT_EQ(enc(neg), (Bytes{0xD7, 0x80, 0xB5, 0x00}));
}

TEST(PduDpv1C2, MalformedPdus) {
  const auto req = [](const Bytes& du) { return error_of(decode_c2_request(du)); };
  const auto res = [](const Bytes& du) { return error_of(decode_c2_response(du)); };
  EXPECT_EQ(req({}), PduError::kTooShort);
  EXPECT_EQ(req({0x57, 0, 0, 0, 0, 0x64}), PduError::kTooShort);
  // S_Len 4 claimed but only 2 address bytes present.
  EXPECT_EQ(req({0x57, 0, 0, 0, 0, 0x64, 1, 0, 0, 0, 0, 0, 0, 4, 0, 0, 0, 0}),
            PduError::kLengthMismatch);
  EXPECT_EQ(res({0x57, 0xF0, 1, 0, 0, 0, 0, 0, 0, 2, 0, 2}), PduError::kLengthMismatch);
  EXPECT_EQ(req({0x58, 0x03, 0x13, 0x00}), PduError::kValueOutOfRange);  // subnet 3
  EXPECT_EQ(req({0x58, 0x00, 0x33, 0x00}), PduError::kValueOutOfRange);  // instance 3
  EXPECT_EQ(req({0x58, 0x00, 0x13}), PduError::kTooShort);
  EXPECT_EQ(req({0x48, 0x00, 0x00}), PduError::kTooLong);
  EXPECT_EQ(req({0x51, 0x00, 0x05, 0x03, 0xAA}), PduError::kLengthMismatch);
  EXPECT_EQ(req({0x5C, 0x00, 0x01, 0x09}), PduError::kBadFunctionCode);  // Alarm_Ack is C1 only
  // Initiate.res whose S_Len (240) is consistent with the bytes present but makes the PDU
  // 252 bytes, beyond the 244-byte DP maximum (found by fuzz_pdu_dpv1_c2).
  Bytes long_res = {0x57, 0xF0, 1, 0, 0, 0, 0x2B, 0x34, 0x57, 0xF0, 0x01, 0x00};
  long_res.resize(12 + 240, 0xFF);
  EXPECT_EQ(res(long_res), PduError::kTooLong);
  EXPECT_EQ(req(long_res), PduError::kTooLong);
  EXPECT_EQ(req({0x56, 0x30, 0x00, 0x64}), PduError::kBadFunctionCode);
  fdl::DataUnit out;
  EXPECT_EQ(error_of(encode(Abort{AbortSubnet::kNone, AbortInstance::kUser, 16, 0}, out)),
            PduError::kValueOutOfRange);
  InitiateRequest big;
  big.s_addr.assign(229, 0);  // 16 + 229 = 245 > 244
  EXPECT_EQ(error_of(encode(big, out)), PduError::kTooLong);
  EXPECT_TRUE(out.empty());
}

}  // namespace
}  // namespace rs4sim::dp::pdu
