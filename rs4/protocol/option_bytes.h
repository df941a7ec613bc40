#pragma once
// Option bytes of RS4 telegrams ([RS4 manual §5.2.3, table 5.2-9]).
//   Option 1 (always): bits 1..0 number of option bytes (1..3), bits 4..2 operating
//     state, bit 5 password follows, bit 6 acknowledge requested, bit 7 reserved.
//   Option 2 (only when a flag is set): field/warning/fault/restart-interlock flags,
//     bit 7 = 1 when option 3 follows.
//   Option 3 (only when a field pair is selected): bits 2..0 first selected pair,
//     bits 5..3 second selected pair, bit 6 reserved, bit 7 = 1.
// None of the three is ever 0x00.

#include "rs4/protocol/errors.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rs4sim::rs4::protocol {

// The operating state a telegram carries in option 1 bits 4..2 (the wire code; the
// scanner model's own state is scanner::ScannerState).
enum class Option1State : std::uint8_t {
  kNone = 0b000,  // in messages to the RS4
  kInitialisation = 0b001,
  kMeasuring = 0b010,
  kConfiguration = 0b011,
  kFault = 0b100,
};

// Option 2, bits 0..6 (bit 7 is derived from the presence of option 3).
struct ScannerFlags {
  bool protective_field_occupied = false;         // bit 0, active protective field
  bool warning_field_occupied = false;            // bit 1, active warning field
  bool warning = false;                           // bit 2
  bool fault = false;                             // bit 3
  bool restart_interlock = false;                 // bit 4
  bool second_protective_field_occupied = false;  // bit 5
  bool second_warning_field_occupied = false;     // bit 6
  bool any() const noexcept;
  friend bool operator==(const ScannerFlags&, const ScannerFlags&) = default;
};

struct OptionBytes {
  Option1State state = Option1State::kNone;
  bool password = false;     // option 1 bit 5: an 8-byte password follows the options
  bool acknowledge = false;  // option 1 bit 6: the RS4 acknowledges (0x16/0x17,
                             // [roboticslibrary/rl LeuzeRs4.cpp])
  ScannerFlags flags;
  std::uint8_t first_field_pair = 0;   // option 3 bits 2..0: 0 none, 1..4
  std::uint8_t second_field_pair = 0;  // option 3 bits 5..3: during a switch-over
  friend bool operator==(const OptionBytes&, const OptionBytes&) = default;
};

inline constexpr std::uint8_t kMaxFieldPair = 4;

// The minimal option bytes: option 3 only with a selected pair, option 2 only with a
// flag or before option 3. kBadFieldPair when a pair number is above 4.
Result<std::size_t> encode_option_bytes(const OptionBytes& options, std::vector<std::uint8_t>& out);

struct DecodedOptions {
  OptionBytes options;
  std::size_t size = 0;  // option bytes consumed (1..3)
};
// Reads option bytes from the start of `bytes` (the byte after the command code).
Result<DecodedOptions> decode_option_bytes(std::span<const std::uint8_t> bytes);

// The body's prefix: options and, with option 1 bit 5, the 8-byte password (ASCII,
// 0xFF-padded, [roboticslibrary/rl LeuzeRs4.cpp]).
using Password = std::array<std::uint8_t, 8>;
struct TelegramPrefix {
  OptionBytes options;
  Password password{};  // meaningful only when options.password
  friend bool operator==(const TelegramPrefix&, const TelegramPrefix&) = default;
};

// Appends CMD, options and (if flagged) the password. kBadFieldPair from the options.
std::error_code encode_prefix(std::uint8_t code, const TelegramPrefix& prefix,
                              std::vector<std::uint8_t>& out);
struct DecodedPrefix {
  std::uint8_t code = 0;
  TelegramPrefix prefix;
  std::size_t size = 0;  // bytes up to the first data byte
};
Result<DecodedPrefix> decode_prefix(std::span<const std::uint8_t> body);

}  // namespace rs4sim::rs4::protocol
