// Block header and flow-control byte ([RS4 manual §5.2.1]; manual tables
// 5.2-1, 5.2-2). Known answers written from the tables, not from the encoder.
#include "rs4/protocol/block.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace rs4sim::rs4::protocol {
namespace {

using Bytes = std::vector<std::uint8_t>;

// --- flow-control byte: one test per state (table 5.2-2, bits 6..4) ---------------------

struct FlowCase {
  FlowState state;
  std::uint8_t state_bits;  // bits 6..4 as in the table
};

class Rs4FlowState : public testing::TestWithParam<FlowCase> {};

TEST_P(Rs4FlowState, EncodesBits6To4AndRoundTrips) {
  const auto [state, bits] = GetParam();
  // bit 0 ready = 1, bit 1 payload = 1, bits 2/3 reserved 0, bits 6..4 state, bit 7 = 0
  const auto expected = static_cast<std::uint8_t>((bits << 4) | 0x03);
  EXPECT_EQ(encode_flow_control({true, true, state}), expected);
  auto decoded = decode_flow_control(expected);
  ASSERT_TRUE(decoded);
  EXPECT_EQ(decoded.value().state, state);
  EXPECT_TRUE(decoded.value().ready);
  EXPECT_TRUE(decoded.value().payload);
}

INSTANTIATE_TEST_SUITE_P(
    AllStates, Rs4FlowState,
    testing::Values(FlowCase{FlowState::kNoCommunicationPath, 0b001},  // no path yet
                    FlowCase{FlowState::kPcAdapterAttached, 0b010},    // PC adapter
                    FlowCase{FlowState::kProxyBusy, 0b011},            // Proxy-FB busy
                    FlowCase{FlowState::kNormal, 0b100},               // normal operation
                    FlowCase{FlowState::kNoConnection, 0b101}));       // no connection

TEST(Rs4FlowControl, NormalReadyWithoutPayloadIs0x41) {
  // 0x41 = 0 100 00 0 1: state 100 normal, bit 1 = 0 no payload, bit 0 = 1 ready
  EXPECT_EQ(encode_flow_control({true, false, FlowState::kNormal}), 0x41);
  auto d = decode_flow_control(0x41);
  ASSERT_TRUE(d);
  EXPECT_EQ(d.value(), (FlowControl{true, false, FlowState::kNormal}));
}

TEST(Rs4FlowControl, NotReadyWithPayloadIs0x42) {
  // 0x42 = 0 100 00 1 0: normal, payload, not ready for a WRITE
  EXPECT_EQ(encode_flow_control({false, true, FlowState::kNormal}), 0x42);
}

TEST(Rs4FlowControl, RejectsReservedBitsAndUndefinedStates) {
  for (const std::uint8_t bad : {std::uint8_t{0x45},     // bit 2 reserved
                                 std::uint8_t{0x49},     // bit 3 reserved
                                 std::uint8_t{0xC1},     // bit 7 reserved
                                 std::uint8_t{0x01},     // state 000 undefined
                                 std::uint8_t{0x00},     // the master's WRITE value: state 000
                                 std::uint8_t{0x61},     // state 110 undefined
                                 std::uint8_t{0x71}}) {  // state 111 undefined
    auto d = decode_flow_control(bad);
    ASSERT_FALSE(d) << int{bad};
    EXPECT_EQ(d.error(), ProtocolError::kBadFlowControl) << int{bad};
  }
}

TEST(Rs4FlowControl, AllByteValuesExhaustively) {
  int valid = 0;
  for (unsigned b = 0; b < 256; ++b) {
    const auto byte = static_cast<std::uint8_t>(b);
    const unsigned state = (b >> 4) & 0x07U;
    const bool expect_ok = (b & 0x8CU) == 0 && state >= 1 && state <= 5;  // table 5.2-2
    auto d = decode_flow_control(byte);
    ASSERT_EQ(static_cast<bool>(d), expect_ok) << b;
    if (d) {
      ++valid;
      EXPECT_EQ(encode_flow_control(d.value()), byte) << b;
      EXPECT_EQ(d.value().ready, (b & 0x01U) != 0);
      EXPECT_EQ(d.value().payload, (b & 0x02U) != 0);
    }
  }
  EXPECT_EQ(valid, 5 * 4);  // 5 states × ready × payload
}

// --- block header ---------------------------------------------------------------------

TEST(Rs4BlockHeader, DecodesSingleLastWriteBlock) {
  const Bytes record{
      0x00,        // 0 flow-control byte: the master writes 0
      0x05,        // 1 block length incl. header = 5
      0xFF, 0xFF,  // 2..3 block number 0xFFFF = last (also the first)
      0x90,        // 4 payload: PROFI_CMD_GET_VERSION
  };
  auto b = decode_block(record, Direction::kWrite);
  ASSERT_TRUE(b);
  EXPECT_EQ(b.value().header, (BlockHeader{0x00, 5, 0xFFFF}));
  EXPECT_TRUE(b.value().header.is_last());
  ASSERT_EQ(b.value().payload.size(), 1U);
  EXPECT_EQ(b.value().payload[0], 0x90);
}

TEST(Rs4BlockHeader, EvaluatesOnlyTheBytesTheHeaderDescribes) {
  const Bytes record{
      0x00,              // 0 flow
      0x07,              // 1 length 7: header + 3 payload bytes
      0xFF, 0xFF,        // 2..3 last block
      0x92, 0x01, 0x01,  // 4..6 payload: 92 mask=measurement mode=permanent
      0xAA, 0xBB,        // 7..8 rest of a fixed-size record, not evaluated ([RS4 manual §5.2])
  };
  auto b = decode_block(record, Direction::kWrite);
  ASSERT_TRUE(b);
  EXPECT_EQ(Bytes(b.value().payload.begin(), b.value().payload.end()), (Bytes{0x92, 0x01, 0x01}));
}

TEST(Rs4BlockHeader, ReadDirectionAcceptsHeaderOnlyBlock) {
  const Bytes record{0x41,         // 0 flow: normal, ready, no payload
                     0x04,         // 1 length 4: header only
                     0xFF, 0xFF};  // 2..3 last block
  auto b = decode_block(record, Direction::kRead);
  ASSERT_TRUE(b);
  EXPECT_TRUE(b.value().payload.empty());
  auto w = decode_block(record, Direction::kWrite);  // WRITE records are ≥ 5 bytes
                                                     // ([RS4 manual §5.2])
  ASSERT_FALSE(w);
  EXPECT_EQ(w.error(), ProtocolError::kRecordTooShort);
}

TEST(Rs4BlockHeader, TypedErrorsForMalformedRecords) {
  struct Case {
    Bytes record;
    Direction direction;
    ProtocolError error;
  };
  const Bytes long_record(241, 0x00);
  const std::vector<Case> cases{
      {{0x00, 0x05, 0xFF}, Direction::kRead, ProtocolError::kRecordTooShort},  // 3 bytes
      {{0x00, 0x05, 0xFF, 0xFF}, Direction::kWrite, ProtocolError::kRecordTooShort},
      {long_record, Direction::kWrite, ProtocolError::kRecordTooLong},  // 241 > 240
      // length byte 4 in a WRITE: no payload (< 5)
      {{0x00, 0x04, 0xFF, 0xFF, 0x90}, Direction::kWrite, ProtocolError::kBlockLengthOutOfRange},
      // length byte 3 in a READ: shorter than the header
      {{0x00, 0x03, 0xFF, 0xFF}, Direction::kRead, ProtocolError::kBlockLengthOutOfRange},
      // length byte 241 > 240
      {{0x00, 0xF1, 0xFF, 0xFF, 0x90}, Direction::kWrite, ProtocolError::kBlockLengthOutOfRange},
      // length byte 6 but the record holds 5 bytes
      {{0x00, 0x06, 0xFF, 0xFF, 0x90}, Direction::kWrite, ProtocolError::kBlockLengthExceedsRecord},
  };
  for (const auto& c : cases) {
    auto b = decode_block(c.record, c.direction);
    ASSERT_FALSE(b);
    EXPECT_EQ(b.error(), c.error) << b.error().message();
  }
}

TEST(Rs4BlockHeader, EncodeBlockWritesHeaderHighByteFirst) {
  Bytes out;
  const Bytes payload{0x14, 0x01};
  ASSERT_FALSE(encode_block(0x43, 0x0102, payload, out));
  const Bytes expected{
      0x43,        // 0 flow: normal, payload, ready
      0x06,        // 1 length 6
      0x01, 0x02,  // 2..3 block number 0x0102, high byte first
      0x14, 0x01,  // 4..5 payload
  };
  EXPECT_EQ(out, expected);
}

TEST(Rs4BlockHeader, EncodeBlockRejectsPayloadAbove236) {
  Bytes out;
  EXPECT_FALSE(encode_block(0x43, 0, Bytes(236, 0x01), out));  // 240-byte block: the maximum
  EXPECT_EQ(out.size(), 240U);
  EXPECT_EQ(out[1], 240);
  Bytes none;
  EXPECT_EQ(encode_block(0x43, 0, Bytes(237, 0x01), none), ProtocolError::kBlockLengthOutOfRange);
  EXPECT_TRUE(none.empty());
}

// --- splitter -------------------------------------------------------------------------

TEST(Rs4BlockSplitter, EmptyAnswerIsOneHeaderOnlyBlock) {
  auto blocks = split_into_blocks({}, {true, true, FlowState::kNormal});
  ASSERT_EQ(blocks.size(), 1U);
  const Bytes expected{0x41,         // 0 flow: normal, ready, payload bit cleared
                       0x04,         // 1 length: header only (DECISION [RS4 manual §5.2.1])
                       0xFF, 0xFF};  // 2..3 last block
  EXPECT_EQ(blocks[0], expected);
}

TEST(Rs4BlockSplitter, ShortAnswerIsOneLastBlock) {
  const Bytes answer{0x93, 0x00, 0x92};
  auto blocks = split_into_blocks(answer, {true, false, FlowState::kNormal});
  ASSERT_EQ(blocks.size(), 1U);
  const Bytes expected{0x43,               // 0 flow: normal, payload, ready
                       0x07,               // 1 length 7
                       0xFF, 0xFF,         // 2..3 last block
                       0x93, 0x00, 0x92};  // 4..6 payload
  EXPECT_EQ(blocks[0], expected);
}

TEST(Rs4BlockSplitter, LargeAnswerUsesBlocksOfAtMost240Bytes) {
  Bytes answer(500);
  for (std::size_t i = 0; i < answer.size(); ++i) answer[i] = static_cast<std::uint8_t>(i);
  auto blocks = split_into_blocks(answer, {false, false, FlowState::kProxyBusy});
  // 500 = 236 + 236 + 28
  ASSERT_EQ(blocks.size(), 3U);
  EXPECT_EQ(blocks[0].size(), 240U);
  EXPECT_EQ((Bytes{blocks[0][0], blocks[0][1], blocks[0][2], blocks[0][3]}),
            (Bytes{0x32, 0xF0, 0x00, 0x00}));  // flow 0 011 00 1 0, len 240, block 0
  EXPECT_EQ((Bytes{blocks[1][0], blocks[1][1], blocks[1][2], blocks[1][3]}),
            (Bytes{0x32, 0xF0, 0x00, 0x01}));  // block 1
  EXPECT_EQ((Bytes{blocks[2][0], blocks[2][1], blocks[2][2], blocks[2][3]}),
            (Bytes{0x32, 0x20, 0xFF, 0xFF}));  // len 32 = 4 + 28, last block
  EXPECT_EQ(blocks[1][4], 236 % 256);          // payload continues where block 0 ended
  EXPECT_EQ(blocks[2][4], 472 % 256);
}

TEST(Rs4BlockSplitter, ExactMultipleOf236HasNoEmptyTrailingBlock) {
  const Bytes answer(472, 0x11);
  BlockSplitter splitter(answer);
  EXPECT_EQ(splitter.remaining_blocks(), 2U);
  auto first = splitter.next({true, false, FlowState::kNormal});
  EXPECT_EQ(first[3], 0x00);  // block 0
  EXPECT_FALSE(splitter.done());
  auto last = splitter.next({false, false, FlowState::kNormal});
  EXPECT_EQ((Bytes{last[0], last[1], last[2], last[3]}), (Bytes{0x42, 0xF0, 0xFF, 0xFF}));
  EXPECT_TRUE(splitter.done());
  EXPECT_TRUE(splitter.next({}).empty());
}

TEST(Rs4BlockSplitter, SmallerBlockSizeForShortRecords) {
  const Bytes answer(10, 0x22);
  auto blocks = split_into_blocks(answer, {true, false, FlowState::kNormal}, 8);  // 4 payload
  ASSERT_EQ(blocks.size(), 3U);                                                   // 4 + 4 + 2
  EXPECT_EQ(blocks[2].size(), 6U);
  EXPECT_EQ(blocks[2][2], 0xFF);
}

}  // namespace
}  // namespace rs4sim::rs4::protocol
