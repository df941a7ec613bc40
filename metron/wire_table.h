#pragma once
// The METRON's byte values. The manual's message figures were lost, so NONE of the values
// below are ReeR's: they are the project's EXTENSION ([docs/metron.md#extension]), kept in
// this one table so that a trace of a real curtain can replace them through the options.
// What the manual does give — the field order, the rules, the error cases — is in
// slave_receiver.h, slave_handler.h and standard_report.h.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rs4sim::metron {

// The 13 slave commands in the manual's order [METRON manual "Slave line mode"].
enum class Command : std::uint8_t {
  kResetSoftware,
  kEnableOssd,
  kDisableOssd,
  kOssdStandby,
  kStartOssdMeasurement,
  kStopOssdMeasurement,
  kStartMeasurement,
  kStopMeasurement,
  kRequestBeamStatus,
  kRequestMeasurements,
  kRequestConfiguration,
  kRequestOssdStatus,
  kRequestCurtainStatus,
};
inline constexpr std::size_t kCommandCount = 13;

// The error answers of the manual's "ERROR HANDLING" paragraphs, numbered as the project
// numbers them: E1 checksum or length > 6, E2 wrong length or bad argument, E3 OSSD state,
// E4 synchronism missing, E5 no Start measurement before Stop measurement.
enum class ErrorCase : std::uint8_t { kE1, kE2, kE3, kE4, kE5 };
inline constexpr std::size_t kErrorCaseCount = 5;

// The measurements a report or command #7/#10 can name. The list is in handbook 8540639,
// not in the seed; these six are the project's EXTENSION. Every value is one byte.
enum class Measurement : std::uint8_t {
  kFirstInterrupted,    // number of the first interrupted beam, 0 when none
  kLastInterrupted,     // number of the last interrupted beam, 0 when none
  kInterruptedCount,    // how many beams are interrupted
  kFreeCount,           // how many beams are free
  kCentralInterrupted,  // (first + last) / 2, 0 when none
  kLongestRun,          // the most consecutive interrupted beams
};
inline constexpr std::size_t kMeasurementCount = 6;

// The fields of a slave reply (figures 15 and 18, lost): which ones a reply carries and in
// what order is the table's (EXTENSION, [docs/metron.md#replies]).
enum class ReplyField : std::uint8_t { kStart, kNode, kLength, kCode, kData, kChecksum };
inline constexpr std::size_t kReplyFieldCount = 6;

// A set of reply fields, bit i = ReplyField i: what the Length byte counts, what the
// checksum sums.
using ReplyFieldSet = std::uint8_t;
[[nodiscard]] constexpr ReplyFieldSet field_bit(ReplyField f) {
  return static_cast<ReplyFieldSet>(1U << static_cast<unsigned>(f));
}
[[nodiscard]] constexpr bool contains(ReplyFieldSet s, ReplyField f) {
  return (s & field_bit(f)) != 0;
}

// DECISION: the reply mirrors the request (slave_reply.h).
inline constexpr std::array<ReplyField, kReplyFieldCount> kMirroredReply{
    ReplyField::kStart, ReplyField::kNode, ReplyField::kLength,
    ReplyField::kCode,  ReplyField::kData, ReplyField::kChecksum};

struct ReplyLayout {
  // The fields a reply carries, in wire order; a field not listed is not sent. The node is
  // sent only in node mode, the data only when the reply has any.
  std::vector<ReplyField> fields =
      std::vector<ReplyField>(kMirroredReply.begin(), kMirroredReply.end());
  // What the Length byte counts (in bytes) and what the checksum sums.
  ReplyFieldSet length_counts = field_bit(ReplyField::kCode) | field_bit(ReplyField::kData);
  ReplyFieldSet checksum_covers = field_bit(ReplyField::kCode) | field_bit(ReplyField::kData);

  friend bool operator==(const ReplyLayout&, const ReplyLayout&) = default;
};

// The parts of a standard-mode report. Table 1 fixes one character before and one after the
// data and a one-character checksum [METRON manual "Standard line mode"]; which is which and
// their order is the table's (EXTENSION, [docs/metron.md#standard-frame]).
enum class ReportField : std::uint8_t { kStart, kData, kChecksum, kEnd };
inline constexpr std::size_t kReportFieldCount = 4;

struct ReportLayout {
  // All four, in wire order (the checksum is sent only when the report has one).
  std::array<ReportField, kReportFieldCount> order{ReportField::kStart, ReportField::kData,
                                                   ReportField::kChecksum, ReportField::kEnd};
  // false: the checksum sums the data values; true: the characters sent for them (digits
  // and separators).
  bool checksum_over_characters = false;

  friend bool operator==(const ReportLayout&, const ReportLayout&) = default;
};

// What the replies of #8, #9 (one beam), #11 and #13 carry: the lost figures held it
// (EXTENSION, [docs/metron.md#replies]). #10 sends one byte per measurement asked for and #12
// "the status of both OSSDs: 0 = OFF, 1 = ON" [METRON manual "Request OSSD status command"];
// those stay fixed.
// #8 Stop measurement: the measurement's code and/or the maximum it reached.
enum class StopItem : std::uint8_t { kCode, kMaximum };
inline constexpr std::size_t kStopItemCount = 2;
// #11 Request configuration: one byte each (times in ms, at most 255).
enum class ConfigItem : std::uint8_t { kBeams, kInputType, kNode, kScanCycle, kTResponse };
inline constexpr std::size_t kConfigItemCount = 5;
// #13 Request light curtain status: one bit each in the status byte.
enum class StatusFlag : std::uint8_t {
  kSynchronised,
  kOssdEnabled,
  kOssdStandby,
  kOssdMeasuring,
  kMeasuring,
  kInterrupted,
  kInputHigh,
};
inline constexpr std::size_t kStatusFlagCount = 7;

struct ReplyData {
  std::vector<StopItem> stop_measurement{StopItem::kMaximum};
  std::uint8_t beam_interrupted = 0x01;  // #9, one beam
  std::uint8_t beam_free = 0x00;
  std::vector<ConfigItem> configuration{ConfigItem::kBeams, ConfigItem::kInputType,
                                        ConfigItem::kNode, ConfigItem::kScanCycle,
                                        ConfigItem::kTResponse};
  // The mask of each flag in #13's byte, StatusFlag order; 0: not reported.
  std::array<std::uint8_t, kStatusFlagCount> curtain_status{0x01, 0x02, 0x04, 0x08,
                                                            0x10, 0x20, 0x40};

  friend bool operator==(const ReplyData&, const ReplyData&) = default;
};

// EXTENSION: every byte value the lost figures held, and the layouts they showed.
struct WireTable {
  // slave line mode
  std::uint8_t frame_start = 0x02;
  std::array<std::uint8_t, kCommandCount> commands{0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07,
                                                   0x08, 0x09, 0x0A, 0x0B, 0x0C, 0x0D};
  std::array<std::uint8_t, kErrorCaseCount> errors{0xE1, 0xE2, 0xE3, 0xE4, 0xE5};
  std::uint8_t all_beams = 0x00;    // #9 data byte asking for all beams; 1..N = one beam
  bool beam_bits_lsb_first = true;  // beam 1 in bit 0 of the first byte
  std::array<std::uint8_t, kMeasurementCount> measurements{0x01, 0x02, 0x03, 0x04, 0x05, 0x06};
  // standard line mode
  std::uint8_t report_start = 0x02;  // STX
  std::uint8_t report_end = 0x03;    // ETX
  std::uint8_t separator = 0x2C;     // ','
  std::uint8_t request_char = 0x3F;  // '?', reporting on request
  // layouts
  ReplyLayout reply;
  ReportLayout report;
  ReplyData replies;

  friend bool operator==(const WireTable&, const WireTable&) = default;
};

// The reply code of a successful command: the command's own code.
[[nodiscard]] inline std::uint8_t code_of(const WireTable& t, Command c) {
  return t.commands[static_cast<std::size_t>(c)];
}
[[nodiscard]] inline std::uint8_t code_of(const WireTable& t, ErrorCase e) {
  return t.errors[static_cast<std::size_t>(e)];
}
[[nodiscard]] inline std::uint8_t code_of(const WireTable& t, Measurement m) {
  return t.measurements[static_cast<std::size_t>(m)];
}
[[nodiscard]] std::optional<Command> command_from_code(const WireTable& t, std::uint8_t code);
[[nodiscard]] std::optional<Measurement> measurement_from_code(const WireTable& t,
                                                               std::uint8_t code);

[[nodiscard]] std::string_view to_string(Command c);
[[nodiscard]] std::string_view to_string(ErrorCase e);
[[nodiscard]] std::string_view to_string(Measurement m);
// "start", "node", "length", "code", "data", "checksum"; "start", "data", "checksum", "end".
[[nodiscard]] std::string_view to_token(ReplyField f);
[[nodiscard]] std::string_view to_token(ReportField f);
[[nodiscard]] std::optional<ReplyField> parse_reply_field(std::string_view token);
[[nodiscard]] std::optional<ReportField> parse_report_field(std::string_view token);
// "code", "maximum"; "beams", "input_type", "node", "scan_cycle", "t_response";
// "synchronised", "ossd_enabled", "ossd_standby", "ossd_measuring", "measuring",
// "interrupted", "input_high".
[[nodiscard]] std::string_view to_token(StopItem i);
[[nodiscard]] std::string_view to_token(ConfigItem i);
[[nodiscard]] std::string_view to_token(StatusFlag f);
[[nodiscard]] std::optional<StopItem> parse_stop_item(std::string_view token);
[[nodiscard]] std::optional<ConfigItem> parse_config_item(std::string_view token);
[[nodiscard]] std::optional<StatusFlag> parse_status_flag(std::string_view token);
// "first", "last", "count", "free", "central", "run".
[[nodiscard]] std::optional<Measurement> parse_measurement(std::string_view name);

// What is wrong with a table: the key of the table it concerns ("commands", "reply.fields";
// the names of the wire-table file, docs/metron.md#wire-table) and why.
struct WireIssue {
  std::string key;
  std::string reason;
};
// nullopt when every code is distinct where it must be and the layouts are whole.
[[nodiscard]] std::optional<WireIssue> check(const WireTable& t);
// Empty when check() finds nothing; otherwise "wire table: " and the reason.
[[nodiscard]] std::string validate(const WireTable& t);

}  // namespace rs4sim::metron
