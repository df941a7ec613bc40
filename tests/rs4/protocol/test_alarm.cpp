// Alarm PDUs ([RS4 manual §5.3, tables 5.3-1, 5.3-2]).
#include "rs4/protocol/alarm.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace rs4sim::rs4::protocol {
namespace {

using Bytes = std::vector<std::uint8_t>;

TEST(Rs4Alarm, UpdateAlarmSequence5) {
  const Bytes expected{
      0x04,  // 1: length incl. header = 4
      0x06,  // 2: type 6 = update alarm
      0x00,  // 3: slot 0
      0x2C,  // 4: 00 101 1 00 = sequence 5, bit 2 ack, no differentiation
  };
  EXPECT_EQ(encode_update_alarm({5}), expected);
  auto d = decode_update_alarm(expected);
  ASSERT_TRUE(d);
  EXPECT_EQ(d.value().sequence, 5);
}

TEST(Rs4Alarm, UpdateAlarmSequence0) {
  EXPECT_EQ(encode_update_alarm({0}), (Bytes{0x04, 0x06, 0x00, 0x04}));
}

TEST(Rs4Alarm, DiagnosisAlarmComing) {
  const DiagnosisAlarm a{3, AlarmDifferentiation::kAppears, 0x2A0B, 0x0002, 0x2418, 0x0101};
  const Bytes expected{
      0x0D,        // 1: length 13 incl. header
      0x01,        // 2: type 1 = diagnosis alarm
      0x00,        // 3: slot 0
      0x1D,        // 4: 00 011 1 01 = sequence 3, ack, appears (DECISION
                   // [docs/decisions.md#rs4-alarm-specifier])
      0x84,        // 5: error from slave
      0x2A, 0x0B,  // 6..7: μC2 error number hi, lo
      0x00, 0x02,  // 8..9: μC2 count hi, lo
      0x24, 0x18,  // 10..11: μC1 error number hi, lo
      0x01, 0x01,  // 12..13: μC1 count hi, lo
  };
  EXPECT_EQ(encode_diagnosis_alarm(a), expected);
  auto d = decode_diagnosis_alarm(expected);
  ASSERT_TRUE(d);
  EXPECT_EQ(d.value(), a);
}

TEST(Rs4Alarm, DiagnosisAlarmGoing) {
  const DiagnosisAlarm a{7, AlarmDifferentiation::kDisappears, 0, 0, 0, 0};
  const Bytes bytes = encode_diagnosis_alarm(a);
  ASSERT_EQ(bytes.size(), 13U);
  EXPECT_EQ(bytes[3], 0x3E);  // 00 111 1 10 = sequence 7, ack, disappears
}

TEST(Rs4Alarm, SpecifierSequenceWrapsModulo8) {
  EXPECT_EQ(alarm_specifier(8, AlarmDifferentiation::kAppears), 0x05);  // 00 000 1 01
  EXPECT_EQ(alarm_specifier(9, AlarmDifferentiation::kNone), 0x0C);     // 00 001 1 00
}

TEST(Rs4Alarm, TypedErrors) {
  const Bytes good = encode_diagnosis_alarm({});
  auto with = [&good](std::size_t at, std::uint8_t v) {
    Bytes b = good;
    b[at] = v;
    return decode_diagnosis_alarm(b);
  };
  EXPECT_EQ(with(0, 0x0C).error(), ProtocolError::kBadAlarmHeader);     // length byte
  EXPECT_EQ(with(1, 0x06).error(), ProtocolError::kBadAlarmHeader);     // type
  EXPECT_EQ(with(2, 0x01).error(), ProtocolError::kBadAlarmHeader);     // slot 1
  EXPECT_EQ(with(3, 0x01).error(), ProtocolError::kBadAlarmSpecifier);  // ack bit clear
  EXPECT_EQ(with(3, 0x45).error(), ProtocolError::kBadAlarmSpecifier);  // bit 6 set
  EXPECT_EQ(with(4, 0x85).error(), ProtocolError::kBadErrorCode);       // not 0x84
  EXPECT_EQ(decode_diagnosis_alarm(Bytes(good.begin(), good.end() - 1)).error(),
            ProtocolError::kTruncated);
  Bytes longer = good;
  longer.push_back(0);
  EXPECT_EQ(decode_diagnosis_alarm(longer).error(), ProtocolError::kTrailingBytes);
  EXPECT_EQ(decode_update_alarm(Bytes{0x04, 0x06, 0x00, 0x05}).error(),
            ProtocolError::kBadAlarmSpecifier);  // update alarm has no differentiation
  EXPECT_EQ(decode_update_alarm(Bytes{0x04, 0x01, 0x00, 0x04}).error(),
            ProtocolError::kBadAlarmHeader);
}

}  // namespace
}  // namespace rs4sim::rs4::protocol
