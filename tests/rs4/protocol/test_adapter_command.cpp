// Adapter commands in a WRITE ([RS4 manual §5.2.2, tables 5.2-3 … 5.2-8]).
#include "rs4/protocol/adapter_command.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace rs4sim::rs4::protocol {
namespace {

using Bytes = std::vector<std::uint8_t>;

WriteCommand parse(const Bytes& payload) {
  auto r = parse_write_command(payload);
  EXPECT_TRUE(r);
  return r ? r.value() : WriteCommand{};
}

RejectedCommand rejected(const Bytes& payload) {
  auto c = parse(payload);
  EXPECT_TRUE(std::holds_alternative<RejectedCommand>(c));
  return std::holds_alternative<RejectedCommand>(c) ? std::get<RejectedCommand>(c)
                                                    : RejectedCommand{};
}

TEST(Rs4AdapterCommand, ResetIs94) {
  EXPECT_TRUE(std::holds_alternative<ResetCommand>(parse({0x94})));  // 5: PROFI_CMD_RESET
  EXPECT_EQ(encode_command(ResetCommand{}), Bytes{0x94});
}

TEST(Rs4AdapterCommand, GetRs4DataMaskAndMode) {
  const Bytes payload{
      0x92,  // 5: PROFI_CMD_GET_RS4_DATA
      0x09,  // 6: mask bit 0 measurement + bit 3 error telegrams
      0x01,  // 7: mode 1 = forward permanently
  };
  auto c = parse(payload);
  ASSERT_TRUE(std::holds_alternative<GetRs4DataCommand>(c));
  const auto& g = std::get<GetRs4DataCommand>(c);
  EXPECT_EQ(g.mask, kForwardMeasurement | kForwardError);
  EXPECT_EQ(g.mode, ForwardMode::kPermanent);
  EXPECT_EQ(encode_command(g), payload);
}

TEST(Rs4AdapterCommand, ForwardMaskBitPerTelegram) {
  // Table 5.2-5 byte 6: bit 0 measurement, bit 1 alive, bit 2 warning, bit 3 error.
  EXPECT_EQ(forward_mask_bit(0x23), 0x01);  // COM_CMD_MESS_16_RT
  EXPECT_EQ(forward_mask_bit(0x14), 0x02);  // COM_CMD_ALIVE
  EXPECT_EQ(forward_mask_bit(0x54), 0x04);  // COM_CMD_WARNING_OCCURE
  EXPECT_EQ(forward_mask_bit(0x53), 0x08);  // COM_CMD_ERROR_OCCURE
  EXPECT_EQ(forward_mask_bit(0x16), 0x00);  // positive acknowledge: not selectable
}

TEST(Rs4AdapterCommand, GetRs4DataMaskZeroStopsForwarding) {
  auto c = parse({0x92, 0x00, 0x00});  // mask 0 = stop all, mode 0
  ASSERT_TRUE(std::holds_alternative<GetRs4DataCommand>(c));
  EXPECT_EQ(std::get<GetRs4DataCommand>(c).mask, 0);
  EXPECT_EQ(std::get<GetRs4DataCommand>(c).mode, ForwardMode::kOnce);
}

TEST(Rs4AdapterCommand, GetRs4DataModeAbove1IsWrongParameter) {
  const auto r = rejected({0x92, 0x01, 0x02});  // mode 2: "> 1 nicht zulässig"
  EXPECT_EQ(r.kind, CommandErrorKind::kWrongParameter);
  EXPECT_EQ(r.command, 0x92);
  EXPECT_EQ(encode_rejection(r), (Bytes{0x93,     // 5: error in telegram
                                        0x01,     // 6: kind 1 = wrong parameter
                                        0x92}));  // 7: the faulty command byte
}

TEST(Rs4AdapterCommand, GetRs4DataUndefinedMaskBitIsWrongParameter) {
  EXPECT_EQ(rejected({0x92, 0x10, 0x00}).kind, CommandErrorKind::kWrongParameter);
  EXPECT_EQ(rejected({0x92, 0x80, 0x01}).kind, CommandErrorKind::kWrongParameter);
}

TEST(Rs4AdapterCommand, GetRs4DataWrongLength) {
  for (const Bytes& p : {Bytes{0x92}, Bytes{0x92, 0x01}, Bytes{0x92, 0x01, 0x00, 0x00}}) {
    const auto r = rejected(p);
    EXPECT_EQ(r.kind, CommandErrorKind::kWrongLength);
    EXPECT_EQ(encode_rejection(r), (Bytes{0x93,     // 5: error in telegram
                                          0x00,     // 6: kind 0 = wrong length
                                          0x92}));  // 7: command byte
  }
}

TEST(Rs4AdapterCommand, SingleByteCommands) {
  EXPECT_TRUE(std::holds_alternative<GetVersionCommand>(parse({0x90})));
  EXPECT_TRUE(std::holds_alternative<GetLastErrorCommand>(parse({0x84})));
  EXPECT_TRUE(std::holds_alternative<GetErrorMemoryCommand>(parse({0x91})));
  EXPECT_EQ(encode_command(GetVersionCommand{}), Bytes{0x90});
  EXPECT_EQ(encode_command(GetLastErrorCommand{}), Bytes{0x84});
  EXPECT_EQ(encode_command(GetErrorMemoryCommand{}), Bytes{0x91});
}

TEST(Rs4AdapterCommand, SingleByteCommandsWithExtraBytesAreWrongLength) {
  for (const std::uint8_t code :
       {std::uint8_t{0x94}, std::uint8_t{0x90}, std::uint8_t{0x84}, std::uint8_t{0x91}}) {
    const auto r = rejected({code, 0x00});
    EXPECT_EQ(r.kind, CommandErrorKind::kWrongLength);
    EXPECT_EQ(r.command, code);
  }
}

TEST(Rs4AdapterCommand, OtherCodesGoToTheRs4Unchanged) {
  // 0x14 COM_CMD_ALIVE with option 1 = 0x01, an RS4 command; 0x93 is an answer code only.
  for (const Bytes& p : {Bytes{0x14, 0x01}, Bytes{0x93, 0x00, 0x92}, Bytes{0x00}, Bytes{0xFF}}) {
    auto c = parse(p);
    ASSERT_TRUE(std::holds_alternative<Rs4Command>(c));
    const auto& fwd = std::get<Rs4Command>(c).bytes;
    EXPECT_EQ(Bytes(fwd.begin(), fwd.end()), p);
  }
}

TEST(Rs4AdapterCommand, EmptyPayloadIsTyped) {
  auto r = parse_write_command({});
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error(), ProtocolError::kEmptyCommand);
}

TEST(Rs4AdapterCommand, DecodeRejection) {
  auto r = decode_rejection(Bytes{0x93, 0x00, 0x84});
  ASSERT_TRUE(r);
  EXPECT_EQ(r.value(), (RejectedCommand{CommandErrorKind::kWrongLength, 0x84}));
  EXPECT_EQ(decode_rejection(Bytes{0x92, 0x00, 0x84}).error(), ProtocolError::kBadAnswerCode);
  EXPECT_EQ(decode_rejection(Bytes{0x93, 0x00}).error(), ProtocolError::kBadAnswerLength);
  EXPECT_EQ(decode_rejection(Bytes{0x93, 0x02, 0x84}).error(), ProtocolError::kBadAnswerValue);
  EXPECT_EQ(decode_rejection(Bytes{}).error(), ProtocolError::kBadAnswerCode);
}

}  // namespace
}  // namespace rs4sim::rs4::protocol
