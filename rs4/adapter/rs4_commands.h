#pragma once
// What the emulated RS4 answers to the commands and telegrams the adapter passes on
// ([RS4 manual §5.2.2, §5.2.3] [roboticslibrary/rl LeuzeRs4.cpp]). Builds RS4 telegram bodies (CMD,
// options, data) from the scanner model; the block header is the adapter's.
//
// One command set for both paths ([RS4 manual §5.2.1] "Alle Kommandos werden transparent von und
// zur RS232 des RS4 übertragen"; DECISION, docs/rs232.md "One command set"): the RS232 port
// (rs4/rs232) and the adapter's acyclic path (rs4/adapter) both go through the rules here.
//   0x10 password check, 0x19 baud, 0x20 measurement window, 0x22 stream switch: validated and
//        executed here; 0x19/0x22 act on the PC-adapter line, which only the RS232 port has
//   0x24 request one scan ([roboticslibrary/rl LeuzeRs4.cpp])  → 0x23 COM_CMD_MESS_16_RT of the
//        last scan, window of the parameter set; 0x53 "no scan" while not scanning
//   0x14 COM_CMD_ALIVE           → 0x14 with the current option bytes
//   0x60..0x65 parameter set     → adapter::ProxySession (proxy_session.h)
//   malformed (options that do not decode, data after 0x14/0x24)
//                                → 0x53 COM_CMD_ERROR_OCCURE "bad data" 0x0504, RS4 protecting
//   anything else                → 0x53 COM_CMD_ERROR_OCCURE "unknown command", RS4 error state
// The password rule (protected_command, password_accepted) is the same on both paths; the
// proxy's own transfer inside a sync it was asked for needs none (DECISION, decisions.md).

#include "rs4/protocol/option_bytes.h"
#include "rs4/scanner/scanner.h"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace rs4sim::rs4::adapter {

inline constexpr std::uint8_t kRs4RequestOneScan = 0x24;  // [roboticslibrary/rl LeuzeRs4.cpp] "00
                                                          // 00 24 01 25 …"
// Error numbers of the emulated RS4's command interpreter (EXTENSION; function 0x0005,
// beside the scanner's fault numbers 0x01xx..0x04xx in docs/rs4-scanner.md).
inline constexpr std::uint16_t kRs4ErrorUnknownCommand = 0x0501;  // parameter: command byte
inline constexpr std::uint16_t kRs4ErrorNoScan = 0x0502;          // parameter: operating state
inline constexpr std::uint16_t kRs4ErrorFunctionCommands = 0x0005;

// Codes of the RS4 command set beyond the manual's telegrams (docs/rs232.md; 0x19 and the
// factory password [roboticslibrary/rl LeuzeRs4.cpp], 0x10/0x20/0x22 EXTENSION).
inline constexpr std::uint8_t kRs4CheckPassword = 0x10;
inline constexpr std::uint8_t kRs4Ack = 0x16;
inline constexpr std::uint8_t kRs4Nak = 0x17;
inline constexpr std::uint8_t kRs4SetBaud = 0x19;
inline constexpr std::uint8_t kRs4MeasurementWindow = 0x20;
inline constexpr std::uint8_t kRs4StreamControl = 0x22;
inline constexpr std::uint16_t kRs4ErrorWrongPassword = 0x0503;   // parameter: command byte
inline constexpr std::uint16_t kRs4ErrorBadData = 0x0504;         // parameter: command byte
inline constexpr std::uint16_t kRs4ErrorNotOperational = 0x0505;  // parameter: operating state
// The public drivers' service password "ROD4LE", 0xFF-padded ([roboticslibrary/rl LeuzeRs4.cpp]).
inline constexpr std::array<std::uint8_t, 8> kFactoryPassword{0x52, 0x4F, 0x44, 0x34,
                                                              0x4C, 0x45, 0xFF, 0xFF};
// 0x19 data: u16 rate code, high byte first ([roboticslibrary/rl LeuzeRs4.cpp] "00 00" = 4800).
inline constexpr std::array<std::uint32_t, 6> kBaudRates{4800, 9600, 19200, 38400, 57600, 115200};
[[nodiscard]] std::optional<std::uint16_t> baud_code(std::uint32_t baud) noexcept;
[[nodiscard]] std::optional<std::uint32_t> baud_of_code(std::uint16_t code) noexcept;

// What a command did: nothing to add, or refused with an error number and its parameter.
struct CommandVerdict {
  std::uint16_t error = 0;
  std::uint16_t parameter = 0;
  [[nodiscard]] bool ok() const noexcept { return error == 0; }
};

// The commands that change the scanner: 0x10, 0x20, 0x62..0x65 ([RS4 manual §3]: a password
// guards the safety settings).
[[nodiscard]] bool protected_command(std::uint8_t code) noexcept;
// OPT1 bit 5 and a password the RS4 accepts: a non-empty user password of its set; while both
// are empty (the factory state), `factory`.
[[nodiscard]] bool password_accepted(const scanner::ParameterSet& set,
                                     const protocol::TelegramPrefix& prefix,
                                     const std::array<std::uint8_t, 8>& factory) noexcept;
// 0x10, 0x19, 0x20, 0x22: the setting commands without an answer telegram of their own.
[[nodiscard]] bool setting_command(std::uint8_t code) noexcept;
// Checks the data of 0x10 (none), 0x19 (a rate code), 0x22 (0 or 1); executes 0x20 (resolution
// u8, start u16, stop u16, [RS4 manual §5.2.3.4]) into the set in the scanner's configuration
// mode ([RS4 manual §7.1.2]: OSSD off, start interlock afterwards).
CommandVerdict execute_setting(scanner::Scanner& rs4, std::uint8_t code,
                               std::span<const std::uint8_t> data, scanner::TimePoint now);
// 0x16 (options, CMD) and 0x17 (options, CMD, error u16) ([roboticslibrary/rl LeuzeRs4.cpp]).
std::vector<std::uint8_t> ack_telegram(const scanner::Scanner& rs4, std::uint8_t code);
std::vector<std::uint8_t> nak_telegram(const scanner::Scanner& rs4, std::uint8_t code,
                                       std::uint16_t error);

// The RS4's answer to one command body (CMD first).
std::vector<std::uint8_t> answer_rs4_command(const scanner::Scanner& rs4,
                                             std::span<const std::uint8_t> command);

// Option 1..3 of the RS4's telegrams, taken from the scanner state ([RS4 manual §5.2.3]).
protocol::TelegramPrefix rs4_prefix(const scanner::Scanner& rs4);

// Telegram bodies with option 1..3 taken from the scanner state ([RS4 manual §5.2.3]).
std::vector<std::uint8_t> alive_telegram(const scanner::Scanner& rs4);
std::vector<std::uint8_t> measurement_telegram(const scanner::Scanner& rs4);  // last scan
std::vector<std::uint8_t> event_telegram(const scanner::Scanner& rs4, const scanner::Rs4Event& e);
std::vector<std::uint8_t> error_telegram(const scanner::Scanner& rs4, std::uint16_t number,
                                         std::uint16_t parameter, std::uint16_t function);

}  // namespace rs4sim::rs4::adapter
