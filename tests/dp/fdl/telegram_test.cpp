// FDL telegram encoding/decoding against the byte examples of [IEC 61158-4-3 frame formats],
// [docs/references.md#dp-worked-example] (worked example, FCS verified),
// [IEC 61158-6-3 MSAC_C1 polling, DPV1 alarms] (DPV1) and the traces cited there.
#include "dp/fdl/telegram.h"

#include "dp/fdl/decoder.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace rs4sim::dp::fdl {
namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes encode_bytes(const Telegram& t) {
  Bytes out;
  const std::size_t n = encode(t, out);
  EXPECT_EQ(n, out.size());
  EXPECT_EQ(encoded_size(t), out.size());
  return out;
}

Telegram decode_ok(const Bytes& frame) {
  Telegram t;
  const std::error_code ec = decode_frame(frame, t);
  EXPECT_FALSE(ec) << ec.message();
  return t;
}

TEST(FdlTelegram, Sd1FdlStatusRequest) {
  const Bytes wire = {
      0x10,  // 0 SD1
      0x05,  // 1 DA = slave 5, no DSAP
      0x02,  // 2 SA = master 2, no SSAP
      0x49,  // 3 FC: request, FCB=0 FCV=0, function 9 = Request FDL status
      0x50,  // 4 FCS = 05+02+49
      0x16,  // 5 ED
  };
  const Telegram t = decode_ok(wire);
  EXPECT_EQ(t.type, FrameType::kSd1);
  EXPECT_EQ(t.da, 5);
  EXPECT_EQ(t.sa, 2);
  EXPECT_TRUE(t.fc.is_request());
  EXPECT_EQ(t.fc.function(), RequestFunction::kFdlStatus);
  EXPECT_FALSE(t.dsap);
  EXPECT_TRUE(t.data.empty());
  EXPECT_EQ(encode_bytes(make_data_telegram(
                5, 2, FrameControl::request(RequestFunction::kFdlStatus, false, false),
                std::nullopt, std::nullopt, {})),
            wire);
}

TEST(FdlTelegram, Sd1FdlStatusReplyAndRs) {
  const Bytes ok = {0x10, 0x02, 0x05,
                    0x00,  // 3 FC: response, station type slave, status OK
                    0x07, 0x16};
  const Bytes rs = {0x10, 0x02, 0x05,
                    0x03,  // 3 FC: response, slave, RS = SAP not enabled (not in DATA_EXCH)
                    0x0A, 0x16};
  EXPECT_EQ(decode_ok(ok).fc.status(), ResponseStatus::kOk);
  EXPECT_EQ(decode_ok(ok).fc.station_type(), StationType::kSlave);
  EXPECT_EQ(decode_ok(rs).fc.status(), ResponseStatus::kSapNotEnabled);
  EXPECT_EQ(
      encode_bytes(make_data_telegram(2, 5, FrameControl::response(ResponseStatus::kSapNotEnabled),
                                      std::nullopt, std::nullopt, {})),
      rs);
}

TEST(FdlTelegram, Sd2SlaveDiagRequestFirstFrame) {
  const Bytes wire = {
      0x68,        // 0 SD2
      0x05, 0x05,  // 1,2 LE = LEr = 5 (DA SA FC DSAP SSAP)
      0x68,        // 3 SD2 repeated
      0x85,        // 4 DA = 5 | 0x80: DSAP follows
      0x82,        // 5 SA = 2 | 0x80: SSAP follows
      0x6D,        // 6 FC: request, FCB=1 FCV=0 (first frame), SRD high
      0x3C,        // 7 DSAP 60 = Slave_Diag
      0x3E,        // 8 SSAP 62 = master MS0
      0xEE,        // 9 FCS = 85+82+6D+3C+3E mod 256
      0x16,        // 10 ED
  };
  const Telegram t = decode_ok(wire);
  EXPECT_EQ(t.type, FrameType::kSd2);
  EXPECT_EQ(t.da, 5);
  EXPECT_EQ(t.sa, 2);
  EXPECT_TRUE(t.fc.fcb());
  EXPECT_FALSE(t.fc.fcv());
  EXPECT_EQ(t.fc.function(), RequestFunction::kSrdHigh);
  EXPECT_EQ(t.dsap, 60);
  EXPECT_EQ(t.ssap, 62);
  EXPECT_TRUE(t.data.empty());
  EXPECT_EQ(encode_bytes(make_data_telegram(
                5, 2, FrameControl::request(RequestFunction::kSrdHigh, true, false), 60, 62, {})),
            wire);
}

TEST(FdlTelegram, Sd2DiagReplyAndItsSd3Form) {
  const Bytes sd2 = {
      0x68, 0x0B, 0x0B, 0x68,  // 0..3 SD2, LE = LEr = 11
      0x82,                    // 4 DA = 2 + DSAP
      0x85,                    // 5 SA = 5 + SSAP
      0x08,                    // 6 FC: response DL (data low)
      0x3E, 0x3C,              // 7,8 DSAP 62, SSAP 60
      0x02, 0x05, 0x00, 0xFF,  // 9..12 Station_Status_1..3, Master_Add FF
      0x12, 0x34,              // 13,14 Ident 0x1234
      0xD5,                    // 15 FCS
      0x16,                    // 16 ED
  };
  const Bytes sd3 = {0xA2,  // 0 SD3: 8 DU bytes incl. DSAP/SSAP
                     0x82, 0x85, 0x08, 0x3E, 0x3C, 0x02, 0x05, 0x00, 0xFF, 0x12, 0x34,
                     0xD5,  // 12 FCS
                     0x16};
  const Telegram a = decode_ok(sd2);
  const Telegram b = decode_ok(sd3);
  EXPECT_EQ(a.type, FrameType::kSd2);
  EXPECT_EQ(b.type, FrameType::kSd3);
  EXPECT_EQ(a.fc.status(), ResponseStatus::kDataLow);
  EXPECT_EQ(a.data, (DataUnit{0x02, 0x05, 0x00, 0xFF, 0x12, 0x34}));
  EXPECT_EQ(b.data, a.data);
  EXPECT_EQ(b.dsap, 62);
  EXPECT_EQ(b.ssap, 60);
  EXPECT_EQ(encode_bytes(a), sd2);
  EXPECT_EQ(encode_bytes(b), sd3);
}

TEST(FdlTelegram, SetPrmChkCfgAndDataExchangeFromWorkedExample) {
  const Bytes set_prm = {0x68, 0x0F, 0x0F, 0x68, 0x85, 0x82,
                         0x5D,        // 6 FC: FCV=1 FCB=0 SRD high
                         0x3D, 0x3E,  // 7,8 DSAP 61 Set_Prm, SSAP 62
                         0x88, 0x0A, 0x01, 0x0B, 0x12, 0x34, 0x00, 0x80, 0x20, 0x00,  // 9..18 DU
                         0x63, 0x16};
  const Bytes dx = {0x68, 0x04, 0x04, 0x68,
                    0x05,  // 4 DA 5, no DSAP = default SAP (Data_Exchange)
                    0x02,  // 5 SA 2
                    0x7D,  // 6 FC: FCV=1 FCB=1 SRD high
                    0xA5,  // 7 output byte
                    0x29, 0x16};
  const Telegram p = decode_ok(set_prm);
  EXPECT_EQ(p.dsap, 61);
  EXPECT_EQ(p.data.size(), 10U);
  EXPECT_EQ(encode_bytes(p), set_prm);
  const Telegram d = decode_ok(dx);
  EXPECT_FALSE(d.dsap);
  EXPECT_FALSE(d.ssap);
  EXPECT_EQ(d.data, (DataUnit{0xA5}));
  EXPECT_EQ(encode_bytes(make_data_telegram(
                5, 2, FrameControl::request(RequestFunction::kSrdHigh, true, true), std::nullopt,
                std::nullopt, std::vector<std::uint8_t>{0xA5})),
            dx);
  // Replies DL (08) and DH (0A, diagnosis pending) with input 3C.
  EXPECT_EQ(
      encode_bytes(make_data_telegram(2, 5, FrameControl::response(ResponseStatus::kDataLow),
                                      std::nullopt, std::nullopt, std::vector<std::uint8_t>{0x3C})),
      (Bytes{0x68, 0x04, 0x04, 0x68, 0x02, 0x05, 0x08, 0x3C, 0x4B, 0x16}));
  EXPECT_EQ(
      encode_bytes(make_data_telegram(2, 5, FrameControl::response(ResponseStatus::kDataHigh),
                                      std::nullopt, std::nullopt, std::vector<std::uint8_t>{0x3C})),
      (Bytes{0x68, 0x04, 0x04, 0x68, 0x02, 0x05, 0x0A, 0x3C, 0x4D, 0x16}));
}

TEST(FdlTelegram, GlobalControlBroadcastClear) {
  const Bytes wire = {0x68, 0x07, 0x07, 0x68,
                      0xFF,        // 4 DA = 127 (broadcast) + DSAP
                      0x82,        // 5 SA 2 + SSAP
                      0x46,        // 6 FC: SDN high, no FCB
                      0x3A, 0x3E,  // 7,8 DSAP 58 Global_Control, SSAP 62
                      0x02, 0x00,  // 9,10 Control_Command Clear_Data, Group_Select 0
                      0x41, 0x16};
  const Telegram t = decode_ok(wire);
  EXPECT_EQ(t.da, kBroadcastAddress);
  EXPECT_EQ(t.fc.function(), RequestFunction::kSdnHigh);
  EXPECT_EQ(encode_bytes(t), wire);
}

TEST(FdlTelegram, TraceTiSlaveDiagAndFestoRs) {
  // [pyprofibus issue #7 trace]: SD2 with LE 11 where SD3 would also fit.
  const Telegram ti = decode_ok({0x68, 0x0B, 0x0B, 0x68, 0xE3, 0x82, 0x08, 0x3E, 0x3C, 0x02, 0x05,
                                 0x00, 0xFF, 0x0C, 0xDA, 0xD3, 0x16});
  EXPECT_EQ(ti.da, 99);
  EXPECT_EQ(ti.sa, 2);
  // [pyprofibus issue #19 trace]: slave 8 answers RS.
  const Telegram festo = decode_ok({0x10, 0x02, 0x08, 0x03, 0x0D, 0x16});
  EXPECT_EQ(festo.fc.status(), ResponseStatus::kSapNotEnabled);
  // [IEC 61158-4-3 frame formats]: Data_Exchange to a slave without outputs is SD1.
  const Telegram dx0 = decode_ok({0x10, 0x05, 0x02, 0x5D, 0x64, 0x16});
  EXPECT_EQ(dx0.type, FrameType::kSd1);
  EXPECT_FALSE(dx0.dsap);
}

TEST(FdlTelegram, Dpv1ReadRequestAndResponse) {
  const Bytes req = {0x68, 0x09, 0x09, 0x68, 0x85, 0x82,
                     0x5C,                    // 6 FC: FCV=1 FCB=0 SRD low
                     0x33, 0x33,              // 7,8 DSAP 51, SSAP 51 (MSAC_C1)
                     0x5E, 0x00, 0x01, 0x10,  // 9..12 Read slot 0 index 1 length 16
                     0x38, 0x16};
  const Bytes res = {0x68, 0x0B, 0x0B, 0x68, 0x82, 0x85, 0x08, 0x33,
                     0x33, 0x5E, 0x00, 0x01, 0x02, 0xAB, 0xCD,  // 9..14 Read.res+ 2 bytes AB CD
                     0x4E, 0x16};
  EXPECT_EQ(encode_bytes(decode_ok(req)), req);
  EXPECT_EQ(encode_bytes(decode_ok(res)), res);
  EXPECT_EQ(decode_ok(res).data, (DataUnit{0x5E, 0x00, 0x01, 0x02, 0xAB, 0xCD}));
}

TEST(FdlTelegram, ShortAckAndToken) {
  EXPECT_EQ(encode_bytes(make_short_ack()), (Bytes{0xE5}));
  EXPECT_EQ(decode_ok({0xE5}).type, FrameType::kShortAck);
  const Bytes token = {0xDC,   // 0 SD4
                       0x02,   // 1 DA 2
                       0x02};  // 2 SA 2 (lone master passes the token to itself,
                               // [IEC 61158-4-3 token])
  EXPECT_EQ(encode_bytes(make_token(2, 2)), token);
  const Telegram t = decode_ok(token);
  EXPECT_EQ(t.type, FrameType::kToken);
  EXPECT_EQ(t.da, 2);
}

TEST(FdlTelegram, FcsIsArithmeticSumMod256) {
  const std::uint8_t bytes[] = {0x85, 0x82, 0x6D, 0x3C, 0x3E};
  EXPECT_EQ(frame_check_sequence(bytes), 0xEE);
  const std::uint8_t carry[] = {0xFF, 0xFF, 0x03};
  EXPECT_EQ(frame_check_sequence(carry), 0x01);
}

// The word-wise sum equals the plain byte sum for every length and alignment.
TEST(FdlTelegram, FcsMatchesByteSumForEveryLengthAndOffset) {
  Bytes bytes(kMaxTelegramSize + 8);
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    bytes[i] = static_cast<std::uint8_t>(i * 37 + 0xA5);
  }
  for (std::size_t offset = 0; offset < 8; ++offset) {
    for (std::size_t n = 0; n + offset <= bytes.size(); ++n) {
      unsigned expected = 0;
      for (std::size_t i = 0; i < n; ++i) expected += bytes[offset + i];
      const std::span<const std::uint8_t> s(bytes.data() + offset, n);
      ASSERT_EQ(frame_check_sequence(s), static_cast<std::uint8_t>(expected)) << n << "@" << offset;
    }
  }
}

TEST(FdlTelegram, MaximumSd2AndEmptySd2) {
  Telegram t =
      make_data_telegram(3, 1, FrameControl::request(RequestFunction::kSrdHigh, true, true), 51, 51,
                         std::vector<std::uint8_t>(244, 0xE5));
  const Bytes wire = encode_bytes(t);
  ASSERT_EQ(wire.size(), kMaxTelegramSize);
  EXPECT_EQ(wire[1], 249);  // LE = 3 + 2 ext + 244
  EXPECT_EQ(decode_ok(wire), t);
  Telegram empty;
  empty.type = FrameType::kSd2;
  empty.da = 1;
  empty.sa = 2;
  empty.fc = FrameControl::response(ResponseStatus::kOk);
  const Bytes empty_wire = {0x68, 0x03, 0x03, 0x68,  // SD2, LE = LEr = 3: DA SA FC only
                            0x01, 0x02, 0x00, 0x03, 0x16};
  EXPECT_EQ(encode_bytes(empty), empty_wire);
  EXPECT_EQ(decode_ok(empty_wire), empty);  // accepted like pyprofibus (LE ≥ 3,
                                            // [IEC 61158-4-3 frame reception])
}

TEST(FdlTelegram, EncodeRejectsBrokenPreconditions) {
  Telegram t = make_data_telegram(
      5, 2, FrameControl::request(RequestFunction::kSrdHigh, true, true), 60, 62, {});
  Bytes out;
  Telegram bad = t;
  bad.ssap.reset();
  EXPECT_THROW(encode(bad, out), std::invalid_argument);  // DSAP without SSAP
  bad = t;
  bad.da = 128;
  EXPECT_THROW(encode(bad, out), std::invalid_argument);
  bad = t;
  bad.type = FrameType::kSd1;
  EXPECT_THROW(encode(bad, out), std::invalid_argument);  // SD1 has no DU
  bad = t;
  bad.type = FrameType::kSd3;
  EXPECT_THROW(encode(bad, out), std::invalid_argument);  // SD3 needs 8 DU bytes
  bad = t;
  bad.dsap = 64;
  EXPECT_THROW(encode(bad, out), std::invalid_argument);
  bad = t;
  bad.data.assign(245, 0);
  EXPECT_THROW(encode(bad, out), std::invalid_argument);  // 245 + 2 > 246
  std::array<std::uint8_t, 4> small{};
  EXPECT_THROW(encode(t, std::span<std::uint8_t>(small)), std::invalid_argument);
  EXPECT_TRUE(out.empty());
}

}  // namespace
}  // namespace rs4sim::dp::fdl
