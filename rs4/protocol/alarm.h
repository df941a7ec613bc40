#pragma once
// Alarm PDUs of the RS4/PROFIsafe ([RS4 manual §5.3], tables 5.3-1
// and 5.3-2). Both carry, in byte 4 (specifier), the sequence number in bits 5..3 and
// bit 2 = 1 (acknowledge required).
//   Update alarm      04 06 00 spec                  (class 2 master wrote first,
//     [RS4 manual §5.3.1])
//   Diagnosis alarm   0D 01 00 spec 84 e2 e2 c2 c2 e1 e1 c1 c1   ([RS4 manual §5.3.2])
// DECISION ([docs/decisions.md#rs4-alarm-specifier]): diagnosis alarm specifier bits 1..0 use the
// DPV1 values 01 (appears) and 10 (disappears) although the manual's table shows 00.

#include "rs4/protocol/errors.h"

#include <cstdint>
#include <span>
#include <vector>

namespace rs4sim::rs4::protocol {

// Specifier bits 1..0 (DPV1 alarm specifier).
enum class AlarmDifferentiation : std::uint8_t {
  kNone = 0b00,        // update alarm (table 5.3-1)
  kAppears = 0b01,     // coming diagnosis alarm
  kDisappears = 0b10,  // going diagnosis alarm (≥ 500 ms without an error)
  kAppearsStillFaulty = 0b11,
};

inline constexpr std::uint8_t kAlarmTypeDiagnosis = 0x01;
inline constexpr std::uint8_t kAlarmTypeUpdate = 0x06;
inline constexpr std::uint8_t kUpdateAlarmSize = 4;
inline constexpr std::uint8_t kDiagnosisAlarmSize = 13;
inline constexpr std::uint8_t kErrorFromSlave = 0x84;
inline constexpr std::uint8_t kMaxAlarmSequence = 7;

struct UpdateAlarm {
  std::uint8_t sequence = 0;  // 0..7
  friend bool operator==(const UpdateAlarm&, const UpdateAlarm&) = default;
};

struct DiagnosisAlarm {
  std::uint8_t sequence = 0;  // 0..7
  AlarmDifferentiation differentiation = AlarmDifferentiation::kAppears;
  std::uint16_t uc2_error = 0;  // error number in μC2 (or of the RS4)
  std::uint16_t uc2_count = 0;  // count of this error since power-up in μC2
  std::uint16_t uc1_error = 0;
  std::uint16_t uc1_count = 0;
  friend bool operator==(const DiagnosisAlarm&, const DiagnosisAlarm&) = default;
};

// The specifier byte; sequence numbers above 7 are reduced modulo 8.
std::uint8_t alarm_specifier(std::uint8_t sequence, AlarmDifferentiation d) noexcept;

std::vector<std::uint8_t> encode_update_alarm(const UpdateAlarm& alarm);
Result<UpdateAlarm> decode_update_alarm(std::span<const std::uint8_t> pdu);

std::vector<std::uint8_t> encode_diagnosis_alarm(const DiagnosisAlarm& alarm);
Result<DiagnosisAlarm> decode_diagnosis_alarm(std::span<const std::uint8_t> pdu);

}  // namespace rs4sim::rs4::protocol
