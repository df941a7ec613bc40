// Adapter error codes, table 5.3-3 ([RS4 manual §5.3.2, table 5.3-3]): one test per code.
#include "rs4/protocol/adapter_error.h"

#include <gtest/gtest.h>

#include <string>

namespace rs4sim::rs4::protocol {
namespace {

void expect_code(AdapterError e, std::uint16_t wire, const std::string& cause_word,
                 const std::string& remedy_word) {
  EXPECT_EQ(to_wire(e), wire);
  ASSERT_EQ(adapter_error_from_wire(wire), e);
  const std::error_code ec = e;
  EXPECT_EQ(&ec.category(), &adapter_category());
  EXPECT_EQ(ec.value(), wire);
  EXPECT_NE(std::string(adapter_error_cause(e)).find(cause_word), std::string::npos);
  EXPECT_NE(std::string(adapter_error_remedy(e)).find(remedy_word), std::string::npos);
  EXPECT_NE(ec.message().find(cause_word), std::string::npos) << ec.message();
}

TEST(Rs4AdapterError, Code2418) {
  expect_code(AdapterError::kSafetyDriverCannotCheckOutputs, 0x2418, "cannot check",
              "PROFIBUS disturbance");
}
TEST(Rs4AdapterError, Code2419) {
  expect_code(AdapterError::kOutputsInconsistent, 0x2419, "no consistent result",
              "PROFIBUS disturbance");
}
TEST(Rs4AdapterError, Code2600) {
  expect_code(AdapterError::kWrongFieldPair, 0x2600, "field pair", "1 to 4");
}
TEST(Rs4AdapterError, Code2A04) {
  expect_code(AdapterError::kTelegramNotProcessed, 0x2A04, "could not be processed",
              "flow-control byte");
}
TEST(Rs4AdapterError, Code2A05) {
  expect_code(AdapterError::kReadBuffersFull, 0x2A05, "read buffers", "fetch the result");
}
TEST(Rs4AdapterError, Code2A06) {
  expect_code(AdapterError::kTelegramTooLong, 0x2A06, "1100", "valid");
}
TEST(Rs4AdapterError, Code2A0B) {
  expect_code(AdapterError::kUnexpectedBlockNumber, 0x2A0B, "block number", "sequentially");
}
TEST(Rs4AdapterError, Code2B01) {
  expect_code(AdapterError::kProxyStateUnknown, 0x2B01, "Proxy-FB", "FB_BUSY");
}
TEST(Rs4AdapterError, Code2B09) {
  expect_code(AdapterError::kCrcComparison, 0x2B09, "CRC comparison", "FB_BUSY");
}
TEST(Rs4AdapterError, Code2B1x) {
  for (std::uint8_t x = 0; x < 16; ++x) {
    const AdapterError e = echo_crc_wrong(x);
    expect_code(e, static_cast<std::uint16_t>(0x2B10 + x), "echo data CRC", "FB_BUSY");
    EXPECT_EQ(crc_number(e), x);
  }
}
TEST(Rs4AdapterError, Code2B2x) {
  for (std::uint8_t x = 0; x < 16; ++x) {
    const AdapterError e = crc_differs_on_reread(x);
    expect_code(e, static_cast<std::uint16_t>(0x2B20 + x), "read repetition", "FB_BUSY");
    EXPECT_EQ(crc_number(e), x);
  }
}

TEST(Rs4AdapterError, UnknownWireValuesAreRejected) {
  for (const int value : {0x0000, 0x2417, 0x241A, 0x2601, 0x2A03, 0x2A07, 0x2A0A, 0x2A0C, 0x2B00,
                          0x2B02, 0x2B08, 0x2B0A, 0x2B30, 0xFFFF}) {
    const auto v = static_cast<std::uint16_t>(value);
    EXPECT_FALSE(adapter_error_from_wire(v)) << std::hex << v;
  }
  EXPECT_FALSE(crc_number(AdapterError::kCrcComparison));
}

TEST(Rs4AdapterError, MessageCarriesHexCode) {
  const std::error_code ec = AdapterError::kUnexpectedBlockNumber;
  EXPECT_EQ(ec.message().substr(0, 8), "0x2A0B: ");
  EXPECT_STREQ(ec.category().name(), "rs4.adapter");
}

}  // namespace
}  // namespace rs4sim::rs4::protocol
