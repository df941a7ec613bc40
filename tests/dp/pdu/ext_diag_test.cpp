// Extended diagnosis blocks ([IEC 61158-6-3 Slave_Diag]) and DPV1 alarm/status PDUs
// ([IEC 61158-6-3 DPV1 alarms, status PDUs]). Vectors: [profirust test_diag_iter] and
// [CP 5613/5614 DP manual p. 187].
#include "dp/pdu/ext_diag.h"

#include "pdu_test_util.h"

namespace rs4sim::dp::pdu {
namespace {

using testing::Bytes;
using testing::error_of;

std::vector<ExtDiagBlock> read_all(const Bytes& ext, bool dpv1) {
  ExtDiagReader reader(ext, dpv1);
  std::vector<ExtDiagBlock> out;
  for (;;) {
    auto r = reader.next();
    EXPECT_TRUE(r) << (r ? "" : r.error().message());
    if (!r || !r.value()) break;
    out.push_back(*r.value());
  }
  return out;
}

std::error_code first_error(const Bytes& ext, bool dpv1) {
  ExtDiagReader reader(ext, dpv1);
  for (int i = 0; i < 64; ++i) {
    auto r = reader.next();
    if (!r) {
      auto after = reader.next();  // the reader stops after an error
      EXPECT_TRUE(after && !after.value());
      return r.error();
    }
    if (!r.value()) break;
  }
  return {};
}

TEST(PduExtDiag, IdentifierBlockModule8) {
  const Bytes ext = {
      0x44,  // 0 b7..6 = 01 identifier-related, length 4 incl. header
      0x00,  // 1 identifiers 0..7: none
      0x01,  // 2 identifiers 8..15: identifier 8
      0x00,  // 3 identifiers 16..23
  };
  const auto blocks = read_all(ext, false);
  ASSERT_EQ(blocks.size(), 1U);
  const auto& id = std::get<IdentifierDiag>(blocks[0]);
  EXPECT_TRUE(id.has_diag(8));
  EXPECT_FALSE(id.has_diag(0));
  EXPECT_FALSE(id.has_diag(9));
  EXPECT_FALSE(id.has_diag(100));
  fdl::DataUnit out;
  ASSERT_TRUE(encode_identifier_diag(std::span<const std::uint8_t>(ext).subspan(1), out));
  EXPECT_EQ(testing::to_bytes(out), ext);
}

TEST(PduExtDiag, ChannelBlock) {
  const Bytes ext = {
      0x82,  // 0 b7..6 = 10 channel-related, identifier 2
      0x41,  // 1 b7..6 = 01 input, channel 1
      0xA1,  // 2 b7..5 = 101 word, b4..0 = 1 short circuit
  };
  const auto blocks = read_all(ext, true);
  ASSERT_EQ(blocks.size(), 1U);
  const ChannelDiag c = std::get<ChannelDiag>(blocks[0]);
  EXPECT_EQ(c, (ChannelDiag{2, ChannelDirection::kInput, 1, 5, 1}));
  fdl::DataUnit out;
  ASSERT_TRUE(encode_channel_diag(c, out));
  EXPECT_EQ(testing::to_bytes(out), ext);
}

TEST(PduExtDiag, ProcessAlarmCp5613) {
  const Bytes ext = {
      0x09,                          // 0 device-related, length 9
      0x02,                          // 1 Alarm_Type 2 = process (b7 = 0: alarm)
      0x03,                          // 2 slot 3
      0x01,                          // 3 specifier: Seq_Nr 0, Add_Ack 0, appears
      0x50, 0x11, 0x22, 0x33, 0x44,  // 4..8 Diagnostic_User_Data
  };
  const auto blocks = read_all(ext, true);
  ASSERT_EQ(blocks.size(), 1U);
  const AlarmPdu a = std::get<AlarmPdu>(blocks[0]);
  EXPECT_EQ(a.alarm_type, alarm_type::kProcess);
  EXPECT_EQ(a.slot, 3);
  EXPECT_EQ(a.seq_nr, 0);
  EXPECT_FALSE(a.add_ack);
  EXPECT_EQ(a.specifier, AlarmSpecifier::kAppears);
  EXPECT_EQ(a.data.size(), 5U);
  fdl::DataUnit out;
  ASSERT_TRUE(encode_alarm(a, out));
  EXPECT_EQ(testing::to_bytes(out), ext);
  // Without DPV1 the same block is plain device-related diagnosis.
  const auto raw = read_all(ext, false);
  EXPECT_EQ(std::get<DeviceDiag>(raw.at(0)).data.size(), 8U);
}

TEST(PduExtDiag, DiagnosticAlarmSpecifierBits) {
  AlarmPdu a;
  a.alarm_type = alarm_type::kDiagnostic;
  a.seq_nr = 1;
  a.add_ack = true;
  a.specifier = AlarmSpecifier::kDisappearsStillFaulty;
  EXPECT_EQ(a.specifier_byte(), 0x0F);  // 00001 1 11
  fdl::DataUnit out;
  ASSERT_TRUE(encode_alarm(a, out));
  EXPECT_EQ(testing::to_bytes(out), (Bytes{0x04, 0x01, 0x00, 0x0F}));
}

TEST(PduExtDiag, StatusMessageCp5613) {
  const Bytes ext = {
      0x07,              // 0 device-related, length 7
      0x81,              // 1 b7 = 1 status, type 1 Status_Message
      0x02,              // 2 slot 2
      0x00,              // 3 specifier: none
      0x05, 0xAA, 0xBB,  // 4..6 data
  };
  const auto blocks = read_all(ext, true);
  ASSERT_EQ(blocks.size(), 1U);
  const StatusPdu s = std::get<StatusPdu>(blocks[0]);
  EXPECT_EQ(s.status_type, status_type::kStatusMessage);
  EXPECT_EQ(s.slot, 2);
  EXPECT_EQ(s.specifier, StatusSpecifier::kNone);
  fdl::DataUnit out;
  ASSERT_TRUE(encode_status(s, out));
  EXPECT_EQ(testing::to_bytes(out), ext);
}

TEST(PduExtDiag, SeveralBlocksInARow) {
  const Bytes ext = {0x44, 0x00, 0x01, 0x00,  // identifier
                     0x82, 0x41, 0xA1,        // channel
                     0xC0,                    // revision byte
                     0x03, 0x12, 0x34};       // device-related (DPV0)
  const auto blocks = read_all(ext, false);
  ASSERT_EQ(blocks.size(), 4U);
  EXPECT_TRUE(std::holds_alternative<IdentifierDiag>(blocks[0]));
  EXPECT_TRUE(std::holds_alternative<ChannelDiag>(blocks[1]));
  EXPECT_EQ(std::get<RevisionBlock>(blocks[2]).header, 0xC0);
  EXPECT_EQ(std::get<DeviceDiag>(blocks[3]).data.size(), 2U);
}

TEST(PduExtDiag, MalformedBlocks) {
  EXPECT_EQ(first_error({0x41, 0x00}, false), PduError::kBadDiagBlock);  // length 1: header only
  EXPECT_EQ(first_error({0x00}, false), PduError::kBadDiagBlock);        // length 0
  EXPECT_EQ(first_error({0x45, 0x00, 0x01}, false), PduError::kBadDiagBlock);   // 5 > 3 present
  EXPECT_EQ(first_error({0x82, 0x41}, false), PduError::kBadDiagBlock);         // channel block cut
  EXPECT_EQ(first_error({0x03, 0x01, 0x00}, true), PduError::kBadAlarm);        // DPV1 block < 4
  EXPECT_EQ(first_error({0x04, 0x00, 0x00, 0x01}, true), PduError::kBadAlarm);  // alarm type 0
  EXPECT_EQ(first_error({0x04, 0x07, 0x00, 0x01}, true), PduError::kBadAlarm);  // type 7 reserved
  EXPECT_EQ(first_error({0x04, 0x7F, 0x00, 0x01}, true), PduError::kBadAlarm);  // type 127
  EXPECT_EQ(first_error({0x04, 0x84, 0x00, 0x00}, true), PduError::kBadAlarm);  // status type 4
  EXPECT_EQ(first_error({0x04, 0x00, 0x00, 0x01}, false), std::error_code{});   // DPV0: raw
}

TEST(PduExtDiag, EncoderRanges) {
  fdl::DataUnit out;
  AlarmPdu a;
  a.seq_nr = 32;
  EXPECT_EQ(error_of(encode_alarm(a, out)), PduError::kValueOutOfRange);
  a.seq_nr = 0;
  a.alarm_type = 0;
  EXPECT_EQ(error_of(encode_alarm(a, out)), PduError::kValueOutOfRange);
  a.alarm_type = 1;
  const Bytes data(60, 0);  // 4 + 60 = 64 > 63
  a.data = data;
  EXPECT_EQ(error_of(encode_alarm(a, out)), PduError::kValueOutOfRange);
  EXPECT_EQ(error_of(encode_device_diag({}, out)), PduError::kValueOutOfRange);
  ChannelDiag c{64, ChannelDirection::kInput, 0, 0, 0};
  EXPECT_EQ(error_of(encode_channel_diag(c, out)), PduError::kValueOutOfRange);
  c = ChannelDiag{0, ChannelDirection::kReserved, 0, 0, 0};
  EXPECT_EQ(error_of(encode_channel_diag(c, out)), PduError::kValueOutOfRange);
  StatusPdu s;
  s.status_type = 29;
  EXPECT_EQ(error_of(encode_status(s, out)), PduError::kValueOutOfRange);
  EXPECT_TRUE(out.empty());
}

}  // namespace
}  // namespace rs4sim::dp::pdu
