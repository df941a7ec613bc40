// Block assembler, WRITE side ([RS4 manual §5.2.1]): blocks 0, 1, … and the last
// 0xFFFF; whole command ≥ 1100 bytes → 0x2A06; out-of-sequence → 0x2A0B.
#include "rs4/protocol/adapter_error.h"
#include "rs4/protocol/block.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace rs4sim::rs4::protocol {
namespace {

using Bytes = std::vector<std::uint8_t>;

// A WRITE record: flow 0, length, number hi/lo, payload of `size` bytes valued `fill`.
Bytes record(std::uint16_t number, std::size_t size, std::uint8_t fill) {
  // Sized once, header written in place: GCC 12 at -O3 misreads insert() after a
  // 4-byte initializer list as an out-of-bounds memmove (-Warray-bounds).
  Bytes r(4 + size, fill);
  r[0] = 0x00;
  r[1] = static_cast<std::uint8_t>(4 + size);
  r[2] = static_cast<std::uint8_t>(number >> 8);
  r[3] = static_cast<std::uint8_t>(number & 0xFF);
  return r;
}

TEST(Rs4BlockAssembler, SingleBlockCommand) {
  BlockAssembler a;
  const Bytes r{0x00,               // 0 flow (master writes 0)
                0x07,               // 1 length 7
                0xFF, 0xFF,         // 2..3 last block
                0x92, 0x0F, 0x01};  // 4..6 PROFI_CMD_GET_RS4_DATA all, permanent
  auto p = a.push(r);
  ASSERT_TRUE(p);
  EXPECT_TRUE(p.value().complete);
  EXPECT_EQ(p.value().blocks_received, 1);
  EXPECT_EQ(Bytes(a.command().begin(), a.command().end()), (Bytes{0x92, 0x0F, 0x01}));
  EXPECT_FALSE(a.in_progress());
}

TEST(Rs4BlockAssembler, ThreeBlocksInSequence) {
  BlockAssembler a;
  auto p0 = a.push(record(0x0000, 236, 0xA0));
  ASSERT_TRUE(p0);
  EXPECT_FALSE(p0.value().complete);
  EXPECT_TRUE(a.in_progress());
  auto p1 = a.push(record(0x0001, 236, 0xA1));
  ASSERT_TRUE(p1);
  EXPECT_FALSE(p1.value().complete);
  auto p2 = a.push(record(0xFFFF, 10, 0xA2));
  ASSERT_TRUE(p2);
  EXPECT_TRUE(p2.value().complete);
  EXPECT_EQ(p2.value().blocks_received, 3);
  ASSERT_EQ(a.command().size(), 482U);
  EXPECT_EQ(a.command()[0], 0xA0);
  EXPECT_EQ(a.command()[236], 0xA1);
  EXPECT_EQ(a.command()[481], 0xA2);
}

TEST(Rs4BlockAssembler, NextCommandStartsFreshAfterCompletion) {
  BlockAssembler a;
  ASSERT_TRUE(a.push(record(0xFFFF, 1, 0x90)));
  auto p = a.push(record(0xFFFF, 1, 0x91));
  ASSERT_TRUE(p);
  EXPECT_EQ(Bytes(a.command().begin(), a.command().end()), (Bytes{0x91}));
}

TEST(Rs4BlockAssembler, OutOfSequenceBlockIs0x2A0B) {
  BlockAssembler a;
  ASSERT_TRUE(a.push(record(0x0000, 10, 0x01)));
  auto p = a.push(record(0x0002, 10, 0x02));  // block 1 skipped
  ASSERT_FALSE(p);
  EXPECT_EQ(p.error(), AdapterError::kUnexpectedBlockNumber);
  EXPECT_EQ(p.error().value(), 0x2A0B);
  EXPECT_FALSE(a.in_progress());  // partial command dropped
}

TEST(Rs4BlockAssembler, FirstBlockNotZeroIs0x2A0B) {
  BlockAssembler a;
  auto p = a.push(record(0x0001, 10, 0x01));
  ASSERT_FALSE(p);
  EXPECT_EQ(p.error(), AdapterError::kUnexpectedBlockNumber);
}

TEST(Rs4BlockAssembler, RepeatedBlockIs0x2A0B) {
  BlockAssembler a;
  ASSERT_TRUE(a.push(record(0x0000, 10, 0x01)));
  auto p = a.push(record(0x0000, 10, 0x01));
  ASSERT_FALSE(p);
  EXPECT_EQ(p.error(), AdapterError::kUnexpectedBlockNumber);
}

TEST(Rs4BlockAssembler, Command1099BytesIsAccepted) {
  BlockAssembler a;
  // 236 * 4 = 944, + 155 = 1099 bytes: the largest command below the 1100 limit
  for (std::uint16_t n = 0; n < 4; ++n) ASSERT_TRUE(a.push(record(n, 236, 0x33)));
  auto p = a.push(record(0xFFFF, 155, 0x33));
  ASSERT_TRUE(p);
  EXPECT_TRUE(p.value().complete);
  EXPECT_EQ(a.command().size(), 1099U);
}

TEST(Rs4BlockAssembler, Command1100BytesIs0x2A06) {
  BlockAssembler a;
  for (std::uint16_t n = 0; n < 4; ++n) ASSERT_TRUE(a.push(record(n, 236, 0x33)));
  auto p = a.push(record(0xFFFF, 156, 0x33));  // 944 + 156 = 1100
  ASSERT_FALSE(p);
  EXPECT_EQ(p.error(), AdapterError::kTelegramTooLong);
  EXPECT_EQ(p.error().value(), 0x2A06);
  // Reported as soon as the limit is crossed, without waiting for the last block.
  BlockAssembler b;
  for (std::uint16_t n = 0; n < 4; ++n) ASSERT_TRUE(b.push(record(n, 236, 0x33)));
  auto q = b.push(record(4, 236, 0x33));
  ASSERT_FALSE(q);
  EXPECT_EQ(q.error(), AdapterError::kTelegramTooLong);
}

TEST(Rs4BlockAssembler, LengthDisagreeingWithRecordIsTyped) {
  BlockAssembler a;
  Bytes r = record(0xFFFF, 3, 0x90);
  r[1] = 9;  // claims 9 bytes, the record holds 7
  auto p = a.push(r);
  ASSERT_FALSE(p);
  EXPECT_EQ(p.error(), ProtocolError::kBlockLengthExceedsRecord);
}

TEST(Rs4BlockAssembler, RecoversWithBlockZeroAfterError) {
  BlockAssembler a;
  ASSERT_FALSE(a.push(record(0x0003, 10, 0x01)));
  ASSERT_TRUE(a.push(record(0x0000, 2, 0x05)));
  auto p = a.push(record(0xFFFF, 2, 0x06));
  ASSERT_TRUE(p);
  EXPECT_EQ(Bytes(a.command().begin(), a.command().end()), (Bytes{0x05, 0x05, 0x06, 0x06}));
}

TEST(Rs4BlockAssembler, ReadDirectionReassemblesSplitterOutput) {
  Bytes answer(700);
  for (std::size_t i = 0; i < answer.size(); ++i) answer[i] = static_cast<std::uint8_t>(i * 7);
  BlockAssembler a(Direction::kRead);
  for (const auto& block : split_into_blocks(answer, {true, false, FlowState::kNormal})) {
    ASSERT_TRUE(a.push(block));
  }
  EXPECT_EQ(Bytes(a.command().begin(), a.command().end()), answer);
  BlockAssembler empty(Direction::kRead);
  auto p = empty.push(Bytes{0x41, 0x04, 0xFF, 0xFF});
  ASSERT_TRUE(p);
  EXPECT_TRUE(p.value().complete);
  EXPECT_TRUE(empty.command().empty());
}

TEST(Rs4BlockAssembler, ReadDirectionHasNo1100Limit) {
  const Bytes answer(2000, 0x5A);  // e.g. a long RS4 answer; the limit is for commands
  BlockAssembler a(Direction::kRead);
  for (const auto& block : split_into_blocks(answer, {true, false, FlowState::kNormal})) {
    ASSERT_TRUE(a.push(block));
  }
  EXPECT_EQ(a.command().size(), 2000U);
  BlockAssembler bounded(Direction::kRead, 1000);
  std::error_code first;
  for (const auto& block : split_into_blocks(answer, {true, false, FlowState::kNormal})) {
    auto p = bounded.push(block);
    if (!p && !first) first = p.error();  // later blocks are then out of sequence
  }
  EXPECT_EQ(first, AdapterError::kTelegramTooLong);
}

}  // namespace
}  // namespace rs4sim::rs4::protocol
