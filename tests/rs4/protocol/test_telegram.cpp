// RS4 telegrams 0x14, 0x53, 0x54 and the dispatch ([RS4 manual §5.2.3]; manual
// tables 5.2-10 … 5.2-12).
#include "rs4/protocol/telegram.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace rs4sim::rs4::protocol {
namespace {

using Bytes = std::vector<std::uint8_t>;

TEST(Rs4Telegram, AliveInMeasuringWithFieldPair1) {
  const Bytes body{
      0x14,  // 5: COM_CMD_ALIVE
      0x0B,  // 6: option 1: 3 option bytes, state 010 measuring
      0x80,  // 7: option 2: no flag, option 3 follows
      0x81,  // 8: option 3: field pair 1
  };
  auto d = decode_telegram(body);
  ASSERT_TRUE(d);
  ASSERT_TRUE(std::holds_alternative<AliveTelegram>(d.value()));
  const auto& alive = std::get<AliveTelegram>(d.value());
  EXPECT_EQ(alive.prefix.options.state, Option1State::kMeasuring);
  EXPECT_EQ(alive.prefix.options.first_field_pair, 1);
  EXPECT_EQ(telegram_code(d.value()), TelegramCode::kAlive);
  auto e = encode_telegram(d.value());
  ASSERT_TRUE(e);
  EXPECT_EQ(e.value(), body);
}

TEST(Rs4Telegram, AliveMinimal) {
  const Bytes body{0x14,   // COM_CMD_ALIVE
                   0x01};  // option 1: one option byte, state none
                           // ([roboticslibrary/rl LeuzeRs4.cpp] "alive, no ack")
  auto e = encode_telegram(AliveTelegram{});
  ASSERT_TRUE(e);
  EXPECT_EQ(e.value(), body);
  auto d = decode_telegram(Bytes{0x14, 0x01, 0x00});
  ASSERT_FALSE(d);
  EXPECT_EQ(d.error(), ProtocolError::kTrailingBytes);
}

TEST(Rs4Telegram, ErrorOccure) {
  ErrorTelegram t;
  t.prefix.options.state = Option1State::kFault;
  t.prefix.options.flags.fault = true;
  t.report = {0x1234, 0x0005, 0xABCD};
  const Bytes expected{
      0x53,        // 5: COM_CMD_ERROR_OCCURE
      0x12,        // 6: option 1: 2 option bytes, state 100 fault
      0x08,        // 7: option 2: bit 3 fault
      0x12, 0x34,  // error number hi, lo
      0x00, 0x05,  // error parameter hi, lo
      0xAB, 0xCD,  // error function hi, lo
  };
  auto e = encode_telegram(t);
  ASSERT_TRUE(e);
  EXPECT_EQ(e.value(), expected);
  auto d = decode_telegram(expected);
  ASSERT_TRUE(d);
  ASSERT_TRUE(std::holds_alternative<ErrorTelegram>(d.value()));
  EXPECT_EQ(std::get<ErrorTelegram>(d.value()), t);
}

TEST(Rs4Telegram, WarningOccureSameLayout) {
  const Bytes body{
      0x54,        // 5: COM_CMD_WARNING_OCCURE (window too dirty)
      0x0A,        // 6: option 1: 2 option bytes, state 010 measuring
      0x04,        // 7: option 2: bit 2 warning
      0x00, 0x2A,  // number
      0x00, 0x01,  // parameter
      0x00, 0x02,  // function
  };
  auto d = decode_telegram(body);
  ASSERT_TRUE(d);
  ASSERT_TRUE(std::holds_alternative<WarningTelegram>(d.value()));
  const auto& w = std::get<WarningTelegram>(d.value());
  EXPECT_TRUE(w.prefix.options.flags.warning);
  EXPECT_EQ(w.report, (ErrorReport{0x002A, 0x0001, 0x0002}));
  auto e = encode_telegram(d.value());
  ASSERT_TRUE(e);
  EXPECT_EQ(e.value(), body);
}

TEST(Rs4Telegram, ErrorReportLengthErrors) {
  auto shorter = decode_telegram(Bytes{0x53, 0x01, 0x00, 0x01, 0x00, 0x02, 0x00});
  ASSERT_FALSE(shorter);
  EXPECT_EQ(shorter.error(), ProtocolError::kTruncated);
  auto longer = decode_telegram(Bytes{0x54, 0x01, 0, 1, 0, 2, 0, 3, 0});
  ASSERT_FALSE(longer);
  EXPECT_EQ(longer.error(), ProtocolError::kTrailingBytes);
}

TEST(Rs4Telegram, UnknownCodeAndEmpty) {
  auto unknown = decode_telegram(Bytes{0x24, 0x01});  // "request one scan" of
                                                      // [roboticslibrary/rl LeuzeRs4.cpp], not
                                                      // forwarded
  ASSERT_FALSE(unknown);
  EXPECT_EQ(unknown.error(), ProtocolError::kUnknownTelegram);
  auto empty = decode_telegram(Bytes{});
  ASSERT_FALSE(empty);
  EXPECT_EQ(empty.error(), ProtocolError::kTruncated);
  auto no_options = decode_telegram(Bytes{0x14});
  ASSERT_FALSE(no_options);
  EXPECT_EQ(no_options.error(), ProtocolError::kTruncated);
}

TEST(Rs4Telegram, EncoderRejectsBadFieldPair) {
  AliveTelegram t;
  t.prefix.options.second_field_pair = 7;
  auto e = encode_telegram(t);
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error(), ProtocolError::kBadFieldPair);
}

}  // namespace
}  // namespace rs4sim::rs4::protocol
