// DPV1 MSAC_C1 PDUs, [IEC 61158-6-3 MSAC_C1, MSAC_C1 polling, DPV1 alarms] (examples
// [IEC 61158-6-3 MSAC_C1] I&M call, [IEC 61158-6-3 MSAC_C1 polling, DPV1 alarms]).
#include "dp/pdu/dpv1.h"

#include "pdu_test_util.h"

namespace rs4sim::dp::pdu {
namespace {

using testing::Bytes;
using testing::enc;
using testing::error_of;

TEST(PduDpv1, ReadRequestFromSection34) {
  const Bytes du = {
      0x5E,  // 0 function Read
      0x00,  // 1 slot 0
      0x01,  // 2 index 1
      0x10,  // 3 Length: up to 16 bytes wanted
  };
  const auto r = decode_c1_request(du);
  ASSERT_TRUE(r);
  EXPECT_EQ(std::get<ReadRequest>(r.value()), (ReadRequest{0, 1, 16}));
  EXPECT_EQ(enc(ReadRequest{0, 1, 16}), du);
}

TEST(PduDpv1, ReadResponseFromSection34) {
  const Bytes du = {0x5E, 0x00, 0x01,
                    0x02,         // 3 Length = bytes returned
                    0xAB, 0xCD};  // 4,5 data
  const auto r = decode_c1_response(du);
  ASSERT_TRUE(r);
  const auto& res = std::get<ReadResponse>(r.value());
  EXPECT_EQ(res.data, (Dpv1Data{0xAB, 0xCD}));
  EXPECT_EQ(enc(res), du);
}

TEST(PduDpv1, NegativeResponseInvalidIndex) {
  const Bytes du = {
      0xDE,  // 0 Read | 0x80
      0x80,  // 1 Error_Decode DPV1
      0xB0,  // 2 Error_Code_1: access / invalid index
      0x00,  // 3 Error_Code_2
  };
  testing::expect_known_answer(
      decode_c1_response, du,
      Dpv1Error{Dpv1Function::kRead, error_decode::kDpv1, ErrorCode1::kInvalidIndex, 0});
  // [IEC 61158-6-3 MSAC_C1]: the negative response to a malformed Write.
  EXPECT_EQ(enc(type_conflict(Dpv1Function::kWrite)), (Bytes{0xDF, 0x80, 0xB3, 0x00}));
}

TEST(PduDpv1, ImCallWriteAndResponse) {
  const Bytes req = {0x5F, 0x00, 0xFF,
                     0x04,                     // 3 Length 4
                     0x08, 0x00, 0xFD, 0xE8};  // 4..7 I&M call header: fn 08, I&M index 65000
  const auto r = decode_c1_request(req);
  ASSERT_TRUE(r);
  const auto& w = std::get<WriteRequest>(r.value());
  EXPECT_EQ(w.slot, 0);
  EXPECT_EQ(w.index, 255);
  EXPECT_EQ(w.data.size(), 4U);
  EXPECT_EQ(enc(w), req);
  const Bytes res = {0x5F, 0x00, 0xFF, 0x04};
  EXPECT_EQ(std::get<WriteResponse>(decode_c1_response(res).value()), (WriteResponse{0, 255, 4}));
  EXPECT_EQ(enc(WriteResponse{0, 255, 4}), res);
}

TEST(PduDpv1, AlarmAckFromSection35) {
  const Bytes du = {
      0x5C,  // 0 Alarm_Ack
      0x00,  // 1 slot 0
      0x01,  // 2 Alarm_Type 1 = diagnostic
      0x09,  // 3 specifier: Seq_Nr 1, appears
  };
  const auto r = decode_c1_request(du);
  ASSERT_TRUE(r);
  const AlarmAck a = std::get<AlarmAck>(r.value());
  EXPECT_EQ(a.seq_nr(), 1);
  EXPECT_EQ(enc(a), du);
  EXPECT_EQ(std::get<AlarmAck>(decode_c1_response(du).value()), a);  // positive reply = echo
}

TEST(PduDpv1, MalformedRequests) {
  const auto err = [](const Bytes& du) { return error_of(decode_c1_request(du)); };
  EXPECT_EQ(err({}), PduError::kTooShort);
  EXPECT_EQ(err({0x5E, 0x00, 0x01}), PduError::kTooShort);
  EXPECT_EQ(err({0x5E, 0x00, 0x01, 0x10, 0x00}), PduError::kLengthMismatch);  // Read.req is 4 bytes
  EXPECT_EQ(err({0x5E, 0x00, 0x01, 0x00}), PduError::kValueOutOfRange);       // Length 0
  EXPECT_EQ(err({0x5E, 0x00, 0x01, 0xF1}), PduError::kValueOutOfRange);       // Length 241
  EXPECT_EQ(err({0x5F, 0x00, 0x01, 0x00}), PduError::kValueOutOfRange);       // Write Length 0
  EXPECT_EQ(err({0x5F, 0x00, 0x01, 0x02, 0xAA}), PduError::kLengthMismatch);  // 1 of 2 bytes
  EXPECT_EQ(err({0x5C, 0x00, 0x01}), PduError::kTooShort);
  EXPECT_EQ(err({0x57, 0x00, 0x00, 0x00}), PduError::kBadFunctionCode);  // C2 Initiate on SAP 51
  EXPECT_EQ(err({0xDE, 0x80, 0xB0, 0x00}), PduError::kBadFunctionCode);  // a response as request
}

TEST(PduDpv1, RejectResponseForMalformedRequests) {
  // [IEC 61158-6-3 MSAC_C1] [VPC3+ dp_msac1.c]: Read with Length 0 → DE 80 B3 00; Write with Length
  // 0 → DF 80 B3 00.
  const auto neg = [](const Bytes& du) {
    EXPECT_FALSE(decode_c1_request(du));
    const auto r = c1_reject_response(du);
    return r ? enc(*r) : Bytes{};
  };
  EXPECT_EQ(neg({0x5E, 0x00, 0x01, 0x00}), (Bytes{0xDE, 0x80, 0xB3, 0x00}));
  EXPECT_EQ(neg({0x5E, 0x00}), (Bytes{0xDE, 0x80, 0xB3, 0x00}));
  EXPECT_EQ(neg({0x5F, 0x00, 0x01, 0x00}), (Bytes{0xDF, 0x80, 0xB3, 0x00}));
  // Unknown function or malformed Alarm_Ack: no PDU reply, the slave leaves DX.
  EXPECT_FALSE(c1_reject_response(Bytes{0x57, 0, 0, 0}));
  EXPECT_FALSE(c1_reject_response(Bytes{0x5C, 0, 1}));
  EXPECT_FALSE(c1_reject_response(Bytes{}));
}

TEST(PduDpv1, MalformedResponses) {
  const auto err = [](const Bytes& du) { return error_of(decode_c1_response(du)); };
  EXPECT_EQ(err({}), PduError::kTooShort);
  EXPECT_EQ(err({0x5E, 0x00, 0x01, 0x03, 0xAA}), PduError::kLengthMismatch);
  EXPECT_EQ(err({0x5F, 0x00, 0x01, 0x03, 0xAA}),
            PduError::kLengthMismatch);  // Write.res has no data
  EXPECT_EQ(err({0xDE, 0x80, 0xB0}), PduError::kTooShort);
  EXPECT_EQ(err({0xC0, 0x80, 0xB0, 0x00}), PduError::kBadFunctionCode);  // 0x40 is no DPV1 function
  EXPECT_EQ(err({0x12}), PduError::kBadFunctionCode);
  EXPECT_EQ(error_of(decode_c1_request(Bytes(245, 0x5F))), PduError::kTooLong);
  EXPECT_EQ(error_of(decode_c1_response(Bytes(245, 0x5E))), PduError::kTooLong);
}

TEST(PduDpv1, EncoderRanges) {
  fdl::DataUnit out;
  EXPECT_EQ(error_of(encode(ReadRequest{0, 0, 0}, out)), PduError::kValueOutOfRange);
  EXPECT_EQ(error_of(encode(ReadRequest{0, 0, 241}, out)), PduError::kValueOutOfRange);
  EXPECT_EQ(error_of(encode(WriteRequest{0, 0, {}}, out)), PduError::kValueOutOfRange);
  EXPECT_EQ(error_of(encode(WriteResponse{0, 0, 241}, out)), PduError::kValueOutOfRange);
  EXPECT_TRUE(out.empty());
  WriteRequest full{1, 2, Dpv1Data(240, 0x5A)};
  ASSERT_TRUE(encode(full, out));
  EXPECT_EQ(out.size(), 244U);  // 4-byte header + 240 = the DP maximum
  EXPECT_EQ(std::get<WriteRequest>(decode_c1_request(testing::to_bytes(out)).value()), full);
}

}  // namespace
}  // namespace rs4sim::dp::pdu
