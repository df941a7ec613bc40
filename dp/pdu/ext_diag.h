#pragma once
// Extended diagnosis blocks of Slave_Diag ([IEC 61158-6-3 Slave_Diag]) and the DPV1 alarm
// and status PDUs carried in the device-related block ([IEC 61158-6-3 DPV1 alarms, status PDUs]).
//
// Header byte bits 7..6: 00 device-related, 01 identifier-related, 10 channel-related
// (fixed 3 bytes), 11 revision/reserved. Bits 5..0: block length incl. header (00/01).

#include "codec/reader.h"
#include "dp/fdl/telegram.h"
#include "dp/pdu/errors.h"

#include <cstdint>
#include <optional>
#include <span>
#include <variant>

namespace rs4sim::dp::pdu {

// Identifier-related block: bit n set ⇔ identifier/module n has diagnosis.
struct IdentifierDiag {
  std::span<const std::uint8_t> bits;  // bytes after the header
  [[nodiscard]] bool has_diag(std::size_t identifier) const;
};

enum class ChannelDirection : std::uint8_t {
  kReserved = 0,
  kInput = 1,
  kOutput = 2,
  kInputOutput = 3
};

// Channel-related block, 3 bytes ([IEC 61158-6-3 Slave_Diag]). Type 1 bit … 6 two words; error 1
// short circuit
// … 9 error, 16–31 manufacturer.
struct ChannelDiag {
  std::uint8_t identifier = 0;  // 0…63
  ChannelDirection direction = ChannelDirection::kInput;
  std::uint8_t channel = 0;       // 0…63
  std::uint8_t channel_type = 0;  // bits 7..5 of byte 3
  std::uint8_t error_type = 0;    // bits 4..0 of byte 3
  friend bool operator==(const ChannelDiag&, const ChannelDiag&) = default;
};

// Alarm_Specifier bits 1..0 ([IEC 61158-6-3 DPV1 alarms]).
enum class AlarmSpecifier : std::uint8_t {
  kNoInfo = 0,
  kAppears = 1,
  kDisappears = 2,
  kDisappearsStillFaulty = 3
};

// Alarm types ([IEC 61158-6-3 DPV1 alarms]); 32…126 manufacturer specific.
namespace alarm_type {
inline constexpr std::uint8_t kDiagnostic = 1;
inline constexpr std::uint8_t kProcess = 2;
inline constexpr std::uint8_t kPull = 3;
inline constexpr std::uint8_t kPlug = 4;
inline constexpr std::uint8_t kStatus = 5;
inline constexpr std::uint8_t kUpdate = 6;
inline constexpr std::uint8_t kManufacturerMin = 32;
inline constexpr std::uint8_t kManufacturerMax = 126;
}  // namespace alarm_type

// DPV1 alarm PDU in the device-related block ([IEC 61158-6-3 DPV1 alarms]).
struct AlarmPdu {
  std::uint8_t alarm_type = alarm_type::kDiagnostic;  // 1…126, bit 7 = 0
  std::uint8_t slot = 0;
  std::uint8_t seq_nr = 0;  // 0…31
  bool add_ack = false;
  AlarmSpecifier specifier = AlarmSpecifier::kNoInfo;
  std::span<const std::uint8_t> data;  // Diagnostic_User_Data (≤ 59 bytes)
  [[nodiscard]] std::uint8_t specifier_byte() const;
};

// Status types ([IEC 61158-6-3 status PDUs]), sent as 0x80 | type.
namespace status_type {
inline constexpr std::uint8_t kStatusMessage = 1;
inline constexpr std::uint8_t kModuleStatus = 2;
inline constexpr std::uint8_t kDxbLinkStatus = 3;
inline constexpr std::uint8_t kPrmCmdAck = 30;
inline constexpr std::uint8_t kRedState = 31;
}  // namespace status_type

enum class StatusSpecifier : std::uint8_t {
  kNone = 0,
  kAppears = 1,
  kDisappears = 2,
  kReserved = 3
};

// DPV1 status PDU in the device-related block ([IEC 61158-6-3 status PDUs]).
struct StatusPdu {
  std::uint8_t status_type = status_type::kStatusMessage;  // 1…126 (without bit 7)
  std::uint8_t slot = 0;
  StatusSpecifier specifier = StatusSpecifier::kNone;
  std::uint8_t specifier_reserved = 0;  // bits 7..2 in place
  std::span<const std::uint8_t> data;
};

// Device-related block of a DPV0 slave (or DPV1 with raw interpretation).
struct DeviceDiag {
  std::span<const std::uint8_t> data;  // bytes after the header
};

// Header bits 7..6 = 11 (VPC3 DIAG_REV_SIGN): kept raw.
struct RevisionBlock {
  std::uint8_t header = 0xC0;
};

using ExtDiagBlock =
    std::variant<DeviceDiag, IdentifierDiag, ChannelDiag, AlarmPdu, StatusPdu, RevisionBlock>;

// Reads the blocks of an extended diagnosis one by one (no allocation; the blocks refer to
// the input bytes). With `dpv1` the device-related blocks are read as alarm/status PDUs.
class ExtDiagReader {
 public:
  ExtDiagReader(std::span<const std::uint8_t> ext_diag, bool dpv1) : in_(ext_diag), dpv1_(dpv1) {}
  // nullopt at the end. Errors: kBadDiagBlock (length 0/1 or beyond the data),
  // kBadAlarm (DPV1 block shorter than 4 bytes). After an error the reader is at its end.
  Result<std::optional<ExtDiagBlock>> next();

 private:
  codec::Reader in_;
  bool dpv1_;
};

// Encoders append one block to `out` (Errors: kValueOutOfRange for fields out of range or
// a block longer than 63 bytes, kTooLong if `out` would exceed the max DU).
Result<void> encode_device_diag(std::span<const std::uint8_t> data, fdl::DataUnit& out);
Result<void> encode_identifier_diag(std::span<const std::uint8_t> bits, fdl::DataUnit& out);
Result<void> encode_channel_diag(const ChannelDiag& c, fdl::DataUnit& out);
Result<void> encode_alarm(const AlarmPdu& a, fdl::DataUnit& out);
Result<void> encode_status(const StatusPdu& s, fdl::DataUnit& out);

}  // namespace rs4sim::dp::pdu
