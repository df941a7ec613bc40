#pragma once
// What a METRON receiver is configured with: the seed's parameters
// [METRON manual "Serial line management"] plus those of handbook 8540639 that the seed only
// names (beam count, scan cycle, t_response), with the project's defaults (DECISION,
// [docs/metron.md#options]). validate() says precisely what is wrong; the app only parses
// flags into this struct.

#include "metron/checksum.h"
#include "metron/wire_table.h"
#include "stream/clock.h"
#include "stream/line_settings.h"

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rs4sim::metron {

enum class LineMode : std::uint8_t { kStandard, kSlave };
enum class Format : std::uint8_t { kBinary, kHex, kDecimal };
enum class ReportingMode : std::uint8_t {
  kContinuous,
  kPeriodical,
  kOnRequest,
  kStatusChange,
  kInputRelated
};
enum class InputType : std::uint8_t {
  kNoFunction,
  kEnableLine,
  kEnableAll,
  kStartStopLine,
  kStartStopAll,
  kLineStandby,
  kAllStandby
};

inline constexpr std::uint8_t kBroadcast = 255;  // [METRON manual "With node"]
// The highest node number: the address is one byte, and 255 is the broadcast address
// [METRON manual "With node"].
inline constexpr std::uint8_t kMaxNode = kBroadcast - 1;
inline constexpr std::uint8_t kMaxLength = 6;    // the length field's maximum, same place
inline constexpr std::uint16_t kMaxBeams = 255;  // one data byte numbers a beam (EXTENSION)

struct Options {
  std::uint16_t beams = 24;
  LineMode line_mode = LineMode::kSlave;
  bool node_enabled = false;
  std::uint8_t node = 1;  // 0..254; 255 is the broadcast address
  InputType input_type = InputType::kNoFunction;
  stream::Duration scan_cycle = std::chrono::milliseconds(10);
  stream::Duration t_response = std::chrono::milliseconds(20);
  stream::Duration reset_time = std::chrono::milliseconds(500);  // deaf after Reset software
  // A message whose bytes stop for this long is dropped as truncated (DECISION).
  stream::Duration receive_timeout = std::chrono::milliseconds(20);
  ChecksumReading checksum_reading = ChecksumReading::kModulo256;
  // standard line mode only
  std::uint32_t baud = 19200;
  stream::Parity parity = stream::Parity::kEven;
  Format format = Format::kBinary;
  bool separator = false;
  bool checksum = false;
  ReportingMode reporting_mode = ReportingMode::kContinuous;
  stream::Duration period = std::chrono::milliseconds(100);
  std::vector<Measurement> report = {Measurement::kFirstInterrupted, Measurement::kLastInterrupted,
                                     Measurement::kInterruptedCount};
  WireTable wire;
  // The initial scene: beams interrupted from the start (1..beams), as gridscan::Options
  // and polaris::Options hold theirs.
  std::vector<std::uint16_t> blocked;

  // Empty when usable; otherwise one sentence naming the option and the allowed values.
  [[nodiscard]] std::string validate() const;
};

// Slave line mode is fixed at 19200 8E1 [METRON manual "Slave line mode"]; standard mode
// runs at the configured rate and parity, 8 data bits, 1 stop bit.
[[nodiscard]] stream::LineSettings line_settings(const Options& o);

// The periods the manual lists for periodical reporting [METRON manual "Periodical reporting"].
[[nodiscard]] bool is_listed_period(stream::Duration period);

[[nodiscard]] std::string_view to_string(LineMode m);
[[nodiscard]] std::string_view to_string(Format f);
[[nodiscard]] std::string_view to_string(ReportingMode m);
[[nodiscard]] std::string_view to_string(InputType t);
[[nodiscard]] std::optional<LineMode> parse_line_mode(std::string_view s);
[[nodiscard]] std::optional<Format> parse_format(std::string_view s);
[[nodiscard]] std::optional<ReportingMode> parse_reporting_mode(std::string_view s);
[[nodiscard]] std::optional<InputType> parse_input_type(std::string_view s);

}  // namespace rs4sim::metron
