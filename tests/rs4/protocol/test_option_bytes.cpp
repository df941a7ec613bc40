// Option bytes 1–3 ([RS4 manual §5.2.3, table 5.2-9]).
#include "rs4/protocol/option_bytes.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace rs4sim::rs4::protocol {
namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes encode(const OptionBytes& o) {
  Bytes out;
  auto n = encode_option_bytes(o, out);
  EXPECT_TRUE(n);
  if (n) {
    EXPECT_EQ(n.value(), out.size());
  }
  return out;
}

TEST(Rs4OptionBytes, OnlyOption1WhenNoFlags) {
  OptionBytes o;
  o.state = Option1State::kMeasuring;
  // 0x09 = 0 0 0 010 01: 1 option byte, state 010 measuring, no password, no ack
  EXPECT_EQ(encode(o), Bytes{0x09});
}

TEST(Rs4OptionBytes, ToTheRs4WithAcknowledgeIs0x41) {
  OptionBytes o;  // state 000 "none" in messages to the RS4
  o.acknowledge = true;
  EXPECT_EQ(encode(o), Bytes{0x41});  // 0 1 0 000 01: ack, 1 option byte
                                      // ([roboticslibrary/rl LeuzeRs4.cpp] set baud)
  o.acknowledge = false;
  o.password = true;
  EXPECT_EQ(encode(o), Bytes{0x21});  // 0 0 1 000 01: password follows
                                      // ([roboticslibrary/rl LeuzeRs4.cpp] password frame)
}

TEST(Rs4OptionBytes, Option2WhenAFlagIsSet) {
  OptionBytes o;
  o.state = Option1State::kFault;
  o.flags.fault = true;
  o.flags.restart_interlock = true;
  const Bytes expected{
      0x12,  // option 1: 0 0 0 100 10 = 2 option bytes, state 100 fault
      0x18,  // option 2: bit 3 fault, bit 4 restart interlock, bit 7 = 0 (no option 3)
  };
  EXPECT_EQ(encode(o), expected);
  auto d = decode_option_bytes(expected);
  ASSERT_TRUE(d);
  EXPECT_EQ(d.value().size, 2U);
  EXPECT_EQ(d.value().options, o);
}

TEST(Rs4OptionBytes, AllOption2FlagBits) {
  OptionBytes o;
  o.flags = {true, true, true, true, true, true, true};
  const Bytes bytes = encode(o);
  ASSERT_EQ(bytes.size(), 2U);
  EXPECT_EQ(bytes[1], 0x7F);  // bits 0..6, bit 7 = 0
  OptionBytes one;
  one.flags.second_warning_field_occupied = true;
  EXPECT_EQ(encode(one)[1], 0x40);  // bit 6
  one.flags = {};
  one.flags.warning_field_occupied = true;
  EXPECT_EQ(encode(one)[1], 0x02);  // bit 1
}

TEST(Rs4OptionBytes, Option3ForcesOption2With0x80) {
  // Worked example of [roboticslibrary/rl LeuzeRs4.cpp]: OPT1 = 0B, OPT2 = 80, OPT3 = 81.
  const Bytes expected{
      0x0B,  // option 1: 0 0 0 010 11 = 3 option bytes, state 010 measuring
      0x80,  // option 2: no flag, bit 7 = 1 because option 3 follows
      0x81,  // option 3: bit 7 = 1, bits 2..0 first pair 1, bits 5..3 second pair 0
  };
  OptionBytes o;
  o.state = Option1State::kMeasuring;
  o.first_field_pair = 1;
  EXPECT_EQ(encode(o), expected);
  auto d = decode_option_bytes(expected);
  ASSERT_TRUE(d);
  EXPECT_EQ(d.value().options, o);
  EXPECT_EQ(d.value().size, 3U);
}

TEST(Rs4OptionBytes, TwoPairsDuringSwitchOver) {
  OptionBytes o;
  o.state = Option1State::kMeasuring;
  o.flags.protective_field_occupied = true;
  o.first_field_pair = 2;
  o.second_field_pair = 4;
  // option 1 0x0B; option 2 0x81 = bit 7 + bit 0; option 3 0xA2 = 1 0 100 010
  EXPECT_EQ(encode(o), (Bytes{0x0B, 0x81, 0xA2}));
}

TEST(Rs4OptionBytes, EncoderRejectsFieldPairAbove4) {
  OptionBytes o;
  o.first_field_pair = 5;
  Bytes out;
  auto r = encode_option_bytes(o, out);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error(), ProtocolError::kBadFieldPair);
}

TEST(Rs4OptionBytes, DecoderTypedErrors) {
  struct Case {
    Bytes bytes;
    ProtocolError error;
  };
  const std::vector<Case> cases{
      {{}, ProtocolError::kTruncated},
      {{0x08}, ProtocolError::kBadOptionCount},  // count 0 (and never 0x00)
      {{0x00}, ProtocolError::kBadOptionCount},
      {{0x89}, ProtocolError::kReservedBitSet},              // bit 7 reserved
      {{0x15}, ProtocolError::kBadOperatingState},           // state 101
      {{0x1D}, ProtocolError::kBadOperatingState},           // state 111
      {{0x0A}, ProtocolError::kTruncated},                   // count 2, option 2 missing
      {{0x0A, 0x00}, ProtocolError::kZeroOptionByte},        // option 2 = 0x00
      {{0x0A, 0x81}, ProtocolError::kBadOptionCount},        // bit 7 but count 2
      {{0x0B, 0x01, 0x81}, ProtocolError::kBadOptionCount},  // count 3, bit 7 clear
      {{0x0B, 0x80}, ProtocolError::kTruncated},             // option 3 missing
      {{0x0B, 0x80, 0x01}, ProtocolError::kOption3MarkerMissing},
      {{0x0B, 0x80, 0xC1}, ProtocolError::kReservedBitSet},  // option 3 bit 6
      {{0x0B, 0x80, 0x85}, ProtocolError::kBadFieldPair},    // first pair 5
      {{0x0B, 0x80, 0xB1}, ProtocolError::kBadFieldPair},    // second pair 6
  };
  for (const auto& c : cases) {
    auto d = decode_option_bytes(c.bytes);
    ASSERT_FALSE(d);
    EXPECT_EQ(d.error(), c.error) << d.error().message();
  }
}

TEST(Rs4OptionBytes, PrefixWithPassword) {
  TelegramPrefix p;
  p.options.password = true;
  p.password = {'R', 'O', 'D', '4', 'L', 'E', 0xFF, 0xFF};
  Bytes out;
  ASSERT_FALSE(encode_prefix(0x10, p, out));
  const Bytes expected{0x10,                                // command
                       0x21,                                // option 1: password
                       0x52, 0x4F, 0x44, 0x34, 0x4C, 0x45,  // "ROD4LE"
                       0xFF, 0xFF};                         // 0xFF padding
  EXPECT_EQ(out, expected);
  auto d = decode_prefix(expected);
  ASSERT_TRUE(d);
  EXPECT_EQ(d.value().code, 0x10);
  EXPECT_EQ(d.value().prefix, p);
  EXPECT_EQ(d.value().size, 10U);
  EXPECT_EQ(decode_prefix(Bytes(expected.begin(), expected.end() - 1)).error(),
            ProtocolError::kTruncated);
}

}  // namespace
}  // namespace rs4sim::rs4::protocol
