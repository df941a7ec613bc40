#pragma once
// The character format of an asynchronous serial line (UART): rate, data bits, parity and
// stop bits, as RS-232/RS-485 devices state it ("115200 8N1", "19200 8E1"). A device core
// reports the format it runs with; a serial transport configures the port with it, and
// the idle-gap framer measures silence in its character times.

#include "stream/clock.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace rs4sim::stream {

enum class Parity : std::uint8_t { kNone, kEven, kOdd };

struct LineSettings {
  std::uint32_t baud = 9600;
  std::uint8_t data_bits = 8;  // 5..8
  Parity parity = Parity::kNone;
  std::uint8_t stop_bits = 1;  // 1 or 2

  friend bool operator==(const LineSettings&, const LineSettings&) = default;
};

// Bits one character takes on the wire: start + data + parity + stop (11 for 8E1, 10 for 8N1).
[[nodiscard]] constexpr unsigned bits_per_character(const LineSettings& s) {
  return 1U + s.data_bits + (s.parity == Parity::kNone ? 0U : 1U) + s.stop_bits;
}

// Time on the wire of `characters` characters (may be fractional: Modbus's 1.5 and 3.5),
// rounded up to the next nanosecond so a gap is never shorter than the rule.
[[nodiscard]] Duration character_time(const LineSettings& s, double characters = 1.0);

// "115200 8N1".
[[nodiscard]] std::string to_string(const LineSettings& s);

// Parses "8N1", "8E1", "7O2" (the format without the rate) into `s`; false when malformed.
[[nodiscard]] bool parse_format(std::string_view text, LineSettings& s);

}  // namespace rs4sim::stream
