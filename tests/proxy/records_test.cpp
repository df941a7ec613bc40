// Byte level: the exact DPV1 records ProxySync writes ([RS4 manual §5.2.1] block header:
// flow byte 00 from the master, block length incl. header, block number hi lo, last 0xFFFF)
// and the Exchange's reading of answer blocks.
#include "proxy/exchange.h"
#include "storage/crc32.h"
#include "tests/proxy/sync_harness.h"

#include <gtest/gtest.h>

namespace rs4sim::proxy::testing {
namespace {

using Bytes = std::vector<std::uint8_t>;

std::vector<Bytes> writes_at(const std::vector<IssuedRecord>& issued, Step step) {
  std::vector<Bytes> out;
  for (const auto& r : issued) {
    if (r.step != step) continue;
    if (const auto* w = std::get_if<RecordWrite>(&r.request)) out.push_back(w->data);
  }
  return out;
}

Bytes concat(Bytes head, std::span<const std::uint8_t> tail) {
  head.insert(head.end(), tail.begin(), tail.end());
  return head;
}

class Records : public ::testing::Test {
 protected:
  void SetUp() override {
    h_.store(set_, "1001");
    h_.device.factory = true;
    h_.device.direction = rs4::protocol::SyncDirection::kDownload;
    ASSERT_TRUE(h_.run_sync());
    ASSERT_EQ(h_.sync->outputs(), FbOutputs{});
    ASSERT_EQ(set_.size(), 8507u);  // 8 chunks of 1024 + 315
  }
  Bytes set_ = SyncHarness::custom_set(3);
  SyncHarness h_;
};

TEST_F(Records, ProxyBeginIdentifyEnd) {
  // 98: header 00 05 FF FF, payload 98 (PROFI_CMD_PROXY_BEGIN)
  EXPECT_EQ(writes_at(h_.issued, Step::kBegin),
            (std::vector<Bytes>{{0x00, 0x05, 0xFF, 0xFF, 0x98}}));
  // IDENTIFY twice: 00 06 FF FF | 60 (IDENTIFY) 01 (option 1, state none)
  const Bytes identify{0x00, 0x06, 0xFF, 0xFF, 0x60, 0x01};
  EXPECT_EQ(writes_at(h_.issued, Step::kIdentify1), std::vector<Bytes>{identify});
  EXPECT_EQ(writes_at(h_.issued, Step::kIdentify2), std::vector<Bytes>{identify});
  // 99 success: 00 08 FF FF | 99 00 (succeeded) 00 00 (no error)
  EXPECT_EQ(writes_at(h_.issued, Step::kEnd),
            (std::vector<Bytes>{{0x00, 0x08, 0xFF, 0xFF, 0x99, 0x00, 0x00, 0x00}}));
}

TEST_F(Records, DownloadBegin) {
  const auto crc = storage::crc32(set_);
  // 00 0C FF FF | 62 01 | size 21 3B (8507) | CRC-32 of the set, high byte first
  const Bytes expected{0x00,
                       0x0C,
                       0xFF,
                       0xFF,
                       0x62,
                       0x01,
                       0x21,
                       0x3B,
                       static_cast<std::uint8_t>(crc >> 24),
                       static_cast<std::uint8_t>(crc >> 16),
                       static_cast<std::uint8_t>(crc >> 8),
                       static_cast<std::uint8_t>(crc)};
  EXPECT_EQ(writes_at(h_.issued, Step::kDownloadBegin), std::vector<Bytes>{expected});
}

TEST_F(Records, DownloadChunks) {
  const auto chunks = writes_at(h_.issued, Step::kDownloadChunk);
  ASSERT_EQ(chunks.size(), 8u * 5u + 2u);  // 1027-byte commands in 5 blocks, the last in 2
  const std::span<const std::uint8_t> set(set_);
  // Chunk 0: payload 63 01 00 + 1024 bytes = 1027 = 4 × 236 + 83.
  EXPECT_EQ(chunks[0], concat({0x00, 0xF0, 0x00, 0x00, 0x63, 0x01, 0x00}, set.subspan(0, 233)));
  EXPECT_EQ(chunks[1], concat({0x00, 0xF0, 0x00, 0x01}, set.subspan(233, 236)));
  EXPECT_EQ(chunks[2], concat({0x00, 0xF0, 0x00, 0x02}, set.subspan(469, 236)));
  EXPECT_EQ(chunks[3], concat({0x00, 0xF0, 0x00, 0x03}, set.subspan(705, 236)));
  EXPECT_EQ(chunks[4], concat({0x00, 0x57, 0xFF, 0xFF}, set.subspan(941, 83)));  // 4 + 83
  // Chunk 8, the last: 63 01 08 + 315 bytes = 318 = 236 + 82.
  EXPECT_EQ(chunks[40], concat({0x00, 0xF0, 0x00, 0x00, 0x63, 0x01, 0x08}, set.subspan(8192, 233)));
  EXPECT_EQ(chunks[41], concat({0x00, 0x56, 0xFF, 0xFF}, set.subspan(8425, 82)));  // 4 + 82
}

TEST_F(Records, ReadsAskForWholeRecords) {
  for (const auto& r : h_.issued) {
    if (const auto* read = std::get_if<RecordRead>(&r.request)) {
      EXPECT_EQ(read->length, 240);
    }
  }
}

// ---- Exchange on hand-made answer blocks
class ExchangeTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const Bytes identify{0x60, 0x01};
    ex_.start(identify, now_, {});
    ASSERT_TRUE(std::holds_alternative<RecordWrite>(*ex_.take_request(now_)));
    ex_.on_result(RecordResult::success(), now_);
  }
  void read(Bytes record) {
    ASSERT_TRUE(std::holds_alternative<RecordRead>(*ex_.take_request(now_)));
    ex_.on_result(RecordResult::success(std::move(record)), now_);
  }
  Exchange ex_;
  dp::TimePoint now_{};
};

TEST_F(ExchangeTest, HeaderOnlyMeansNotReadyAndPollsLater) {
  read({0x31, 0x04, 0xFF, 0xFF});  // flow: ready, no payload, proxy busy
  EXPECT_EQ(ex_.status(), Exchange::Status::kBusy);
  EXPECT_FALSE(ex_.take_request(now_));  // the poll interval first
  now_ += ExchangeTiming{}.poll_interval;
  read({0x33, 0x07, 0x00, 0x00, 0x60, 0x02, 0x00});  // block 0: 60 opt status
  read({0x33, 0x06, 0xFF, 0xFF, 0xAB, 0xCD});        // last block
  ASSERT_EQ(ex_.status(), Exchange::Status::kDone);
  EXPECT_EQ(Bytes(ex_.answer().begin(), ex_.answer().end()), (Bytes{0x60, 0x02, 0x00, 0xAB, 0xCD}));
}

TEST_F(ExchangeTest, BlockOutOfSequenceIsABadRecord) {
  read({0x33, 0x05, 0x00, 0x00, 0x60});
  read({0x33, 0x05, 0x00, 0x02, 0x01});  // block 2 after block 0
  EXPECT_EQ(ex_.status(), Exchange::Status::kBadRecord);
}

TEST_F(ExchangeTest, LengthByteBeyondTheRecordIsABadRecord) {
  read({0x33, 0x09, 0xFF, 0xFF, 0x60});
  EXPECT_EQ(ex_.status(), Exchange::Status::kBadRecord);
}

TEST_F(ExchangeTest, ForwardedTelegramIsSkipped) {
  read({0x33, 0x06, 0xFF, 0xFF, 0x14, 0x09});  // 0x14 COM_CMD_ALIVE forwarded
  EXPECT_EQ(ex_.status(), Exchange::Status::kBusy);
  read({0x33, 0x06, 0xFF, 0xFF, 0x60, 0x02});
  EXPECT_EQ(ex_.status(), Exchange::Status::kDone);
}

// ERROR_CODE_SFC is the S7 RET_VAL of the failed RD_REC: W#16#80 + Error_Code_1 (0xB5 state
// conflict → 0x80B5); Error_Code_2 has no place in it [docs/decisions.md#proxy-error-code-sfc].
TEST_F(ExchangeTest, RefusedReadCarriesTheDpv1ErrorAsSfc) {
  ASSERT_TRUE(ex_.take_request(now_));
  ex_.on_result(RecordResult::negative(0xB5, 0x07), now_);
  EXPECT_EQ(ex_.status(), Exchange::Status::kReadFailed);
  EXPECT_EQ(ex_.sfc(), 0x80B5);
}

TEST_F(ExchangeTest, ReadWithoutResponseIs80C5) {
  ASSERT_TRUE(ex_.take_request(now_));
  ex_.on_result(RecordResult::no_response(), now_);
  EXPECT_EQ(ex_.status(), Exchange::Status::kReadFailed);
  EXPECT_EQ(ex_.sfc(), 0x80C5);
}

TEST_F(ExchangeTest, NoAnswerUntilTheDeadlineIsAReadFailure) {
  for (int i = 0; i < 20000 && ex_.status() == Exchange::Status::kBusy; ++i) {
    now_ = *ex_.next_wakeup();
    ex_.tick(now_);
    if (auto r = ex_.take_request(now_))
      ex_.on_result(RecordResult::success({0x31, 0x04, 0xFF, 0xFF}), now_);
  }
  EXPECT_EQ(ex_.status(), Exchange::Status::kReadFailed);
  EXPECT_EQ(ex_.sfc(), 0);
  EXPECT_GE(now_, dp::TimePoint{} + ExchangeTiming{}.answer_timeout);
}

}  // namespace
}  // namespace rs4sim::proxy::testing
