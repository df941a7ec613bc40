#pragma once
// PROFIBUS baud rates and wire timing, [IEC 61158-4-3 UART character, bus parameters, timing]
// [IEC 61158-2 baud rates]: the one table the links (wire model, serial speed) and the master (bus
// parameters) share.
//
// One UART character is 11 bits (start, 8 data LSB first, even parity, stop;
// [IEC 61158-4-3 UART character] [IEC 61158-2 baud rates]). All FDL times are counted in bit times
// Tbit = 1/baud. Before every request the line is idle for TSYN = 33 Tbit; a responder waits at
// least min TSDR (default 11 Tbit) after the end of the request
// ([IEC 61158-4-3 bus parameters, timing]).

#include "dp/time/clock.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace rs4sim::dp {

// The standard PROFIBUS-DP (RS-485) rates in bit/s, [IEC 61158-4-3 UART character]
// [IEC 61158-2 baud rates] (31.25k is MBP/PA only).
enum class BaudRate : std::uint32_t {
  k9k6 = 9'600,
  k19k2 = 19'200,
  k45k45 = 45'450,
  k93k75 = 93'750,
  k187k5 = 187'500,
  k500k = 500'000,
  k1M5 = 1'500'000,
  k3M = 3'000'000,
  k6M = 6'000'000,
  k12M = 12'000'000,
};

inline constexpr std::array<BaudRate, 10> kStandardBaudRates = {
    BaudRate::k9k6,  BaudRate::k19k2, BaudRate::k45k45, BaudRate::k93k75, BaudRate::k187k5,
    BaudRate::k500k, BaudRate::k1M5,  BaudRate::k3M,    BaudRate::k6M,    BaudRate::k12M};

inline constexpr std::uint32_t kBitsPerCharacter = 11;  // [IEC 61158-4-3 UART character]
                                                        // [IEC 61158-2 baud rates]
inline constexpr std::uint32_t kTsynBits = 33;          // [IEC 61158-4-3 bus parameters, timing]
                                                        // TSYN
inline constexpr std::uint32_t kMinTsdrBits = 11;       // [IEC 61158-4-3 bus parameters, timing]
                                                        // default min TSDR
inline constexpr std::uint32_t kTid1Bits = 37;          // idle after a reply
                                                        // ([COM PROFIBUS bus-parameter printout])

// The [IEC 61158-4-3 bus parameters, timing] default bus times at one rate, in bit times
// ([Felser PROFIBUS manual, time ratios table]).
struct DefaultBusTimes {
  std::uint32_t tqui, tset, max_tsdr, tsl;
};
[[nodiscard]] constexpr DefaultBusTimes default_bus_times(BaudRate b) {
  switch (b) {
    case BaudRate::k500k: return {0, 1, 100, 200};
    case BaudRate::k1M5: return {0, 1, 150, 300};
    case BaudRate::k3M: return {3, 4, 250, 400};
    case BaudRate::k6M: return {6, 8, 450, 600};
    case BaudRate::k12M: return {9, 16, 800, 1000};
    default: return {0, 1, 60, 100};  // ≤ 187.5 kbit/s
  }
}

[[nodiscard]] constexpr std::uint32_t bits_per_second(BaudRate b) {
  return static_cast<std::uint32_t>(b);
}

// The standard rate with exactly this many bit/s, if any.
[[nodiscard]] std::optional<BaudRate> baud_rate_from_bps(std::uint64_t bps);

// Parses "9600", "1500000", "187.5k", "1.5M", "12M", "45.45k" (case-insensitive suffix).
// nullopt when the text is not a number or not a standard rate.
[[nodiscard]] std::optional<BaudRate> parse_baud_rate(std::string_view text);

// "9.6k, 19.2k, … 12M": for error messages.
[[nodiscard]] std::string standard_baud_rate_list();

// Human form of a rate ("1.5M", "187.5k").
[[nodiscard]] std::string to_string(BaudRate b);

// Time `bits` bit times take at `b`, rounded up to the clock's tick (nanoseconds).
[[nodiscard]] Duration bit_time(BaudRate b, std::uint64_t bits);

// Bits one telegram of `bytes` characters occupies on the line ([IEC 61158-4-3 UART character]
// [IEC 61158-2 baud rates]: 11 bit/char).
[[nodiscard]] constexpr std::uint64_t telegram_bits(std::size_t bytes) {
  return static_cast<std::uint64_t>(bytes) * kBitsPerCharacter;
}

}  // namespace rs4sim::dp
