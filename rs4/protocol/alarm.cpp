#include "rs4/protocol/alarm.h"

#include "codec/reader.h"
#include "codec/writer.h"

namespace rs4sim::rs4::protocol {
namespace {

constexpr std::uint8_t kSlot0 = 0x00;
constexpr std::uint8_t kAckBit = 0x04;
constexpr unsigned kSequenceShift = 3;
constexpr std::uint8_t kSequenceMask = 0x07;
constexpr std::uint8_t kDifferentiationMask = 0x03;
constexpr std::uint8_t kSpecifierReserved = 0xC0;

std::error_code check_header(std::span<const std::uint8_t> pdu, std::uint8_t size,
                             std::uint8_t type) noexcept {
  if (pdu.size() < size) return ProtocolError::kTruncated;
  if (pdu.size() > size) return ProtocolError::kTrailingBytes;
  if (pdu[0] != size || pdu[1] != type || pdu[2] != kSlot0) return ProtocolError::kBadAlarmHeader;
  if ((pdu[3] & kSpecifierReserved) != 0 || (pdu[3] & kAckBit) == 0) {
    return ProtocolError::kBadAlarmSpecifier;
  }
  return {};
}

std::uint8_t sequence_of(std::uint8_t specifier) noexcept {
  return static_cast<std::uint8_t>((specifier >> kSequenceShift) & kSequenceMask);
}

}  // namespace

std::uint8_t alarm_specifier(std::uint8_t sequence, AlarmDifferentiation d) noexcept {
  return static_cast<std::uint8_t>(((sequence & kSequenceMask) << kSequenceShift) | kAckBit |
                                   (static_cast<std::uint8_t>(d) & kDifferentiationMask));
}

std::vector<std::uint8_t> encode_update_alarm(const UpdateAlarm& alarm) {
  return {kUpdateAlarmSize, kAlarmTypeUpdate, kSlot0,
          alarm_specifier(alarm.sequence, AlarmDifferentiation::kNone)};
}

Result<UpdateAlarm> decode_update_alarm(std::span<const std::uint8_t> pdu) {
  if (auto ec = check_header(pdu, kUpdateAlarmSize, kAlarmTypeUpdate)) return ec;
  // Table 5.3-1: "keine Alarm-Differenzierung", bits 1..0 = 00.
  if ((pdu[3] & kDifferentiationMask) != 0) return ProtocolError::kBadAlarmSpecifier;
  return UpdateAlarm{sequence_of(pdu[3])};
}

std::vector<std::uint8_t> encode_diagnosis_alarm(const DiagnosisAlarm& alarm) {
  std::vector<std::uint8_t> out{kDiagnosisAlarmSize, kAlarmTypeDiagnosis, kSlot0,
                                alarm_specifier(alarm.sequence, alarm.differentiation),
                                kErrorFromSlave};
  out.reserve(kDiagnosisAlarmSize);
  codec::Appender w(out);
  for (const auto v : {alarm.uc2_error, alarm.uc2_count, alarm.uc1_error, alarm.uc1_count}) {
    w.u16_be(v);
  }
  return out;
}

Result<DiagnosisAlarm> decode_diagnosis_alarm(std::span<const std::uint8_t> pdu) {
  if (auto ec = check_header(pdu, kDiagnosisAlarmSize, kAlarmTypeDiagnosis)) return ec;
  if (pdu[4] != kErrorFromSlave) return ProtocolError::kBadErrorCode;
  codec::Reader r(pdu.subspan(5));
  return DiagnosisAlarm{
      sequence_of(pdu[3]), static_cast<AlarmDifferentiation>(pdu[3] & kDifferentiationMask),
      r.u16_be(),          r.u16_be(),
      r.u16_be(),          r.u16_be()};
}

}  // namespace rs4sim::rs4::protocol
