#pragma once
// What the emulated RS4 answers to the commands and telegrams the adapter passes on
// ([RS4 manual §5.2.2, §5.2.3] [roboticslibrary/rl LeuzeRs4.cpp]). Builds RS4 telegram bodies (CMD,
// options, data) from the scanner model; the block header is the adapter's.
//
// Commands the emulated RS4 answers (DECISION, docs/rs4-adapter.md):
//   0x24 request one scan ([roboticslibrary/rl LeuzeRs4.cpp])  → 0x23 COM_CMD_MESS_16_RT of the
//     last scan, window of
//                                   the parameter set; 0x53 "no scan" while not scanning
//   0x14 COM_CMD_ALIVE           → 0x14 with the current option bytes
//   anything else / malformed    → 0x53 COM_CMD_ERROR_OCCURE "unknown command"
// The transfer commands 0x60..0x65 of the proxy ([docs/proxy-protocol.md]) have state; the
// Adapter routes them to its ProxySession (proxy_session.h) before this function.

#include "rs4/protocol/option_bytes.h"
#include "rs4/scanner/scanner.h"

#include <cstdint>
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
