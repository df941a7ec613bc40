#pragma once
// RS4 telegrams forwarded to the master ([RS4 manual §5.2.3],
// tables 5.2-10 … 5.2-14). A telegram body is
//   CMD | option 1 [option 2 [option 3]] | [8-byte password if option 1 bit 5] | data
// On PROFIBUS it travels behind the block header; behind the optical PC adapter inside
// the RS232 frame ([roboticslibrary/rl LeuzeRs4.cpp], rs232.h).

#include "rs4/protocol/errors.h"
#include "rs4/protocol/measurement.h"
#include "rs4/protocol/option_bytes.h"

#include <array>
#include <cstdint>
#include <span>
#include <variant>
#include <vector>

namespace rs4sim::rs4::protocol {

enum class TelegramCode : std::uint8_t {
  kAlive = 0x14,          // COM_CMD_ALIVE ([RS4 manual §5.2.3.1])
  kMess16Rt = 0x23,       // COM_CMD_MESS_16_RT ([RS4 manual §5.2.3.4])
  kErrorOccure = 0x53,    // COM_CMD_ERROR_OCCURE ([RS4 manual §5.2.3.2])
  kWarningOccure = 0x54,  // COM_CMD_WARNING_OCCURE ([RS4 manual §5.2.3.3])
};

struct AliveTelegram {  // 0x14: no data
  TelegramPrefix prefix;
  friend bool operator==(const AliveTelegram&, const AliveTelegram&) = default;
};

// Data of 0x53 / 0x54: number, parameter, function of the RS4, each high byte first.
struct ErrorReport {
  std::uint16_t number = 0;
  std::uint16_t parameter = 0;
  std::uint16_t function = 0;
  friend bool operator==(const ErrorReport&, const ErrorReport&) = default;
};
struct ErrorTelegram {  // 0x53
  TelegramPrefix prefix;
  ErrorReport report;
  friend bool operator==(const ErrorTelegram&, const ErrorTelegram&) = default;
};
struct WarningTelegram {  // 0x54, e.g. window too dirty
  TelegramPrefix prefix;
  ErrorReport report;
  friend bool operator==(const WarningTelegram&, const WarningTelegram&) = default;
};

using Rs4Telegram =
    std::variant<AliveTelegram, ErrorTelegram, WarningTelegram, MeasurementTelegram>;

TelegramCode telegram_code(const Rs4Telegram& telegram) noexcept;
bool is_known_code(std::uint8_t code) noexcept;  // one of the four codes above

Result<std::vector<std::uint8_t>> encode_telegram(const Rs4Telegram& telegram);
// kUnknownTelegram for any other command byte; fixed-size telegrams reject missing
// (kTruncated) and extra (kTrailingBytes) bytes.
Result<Rs4Telegram> decode_telegram(std::span<const std::uint8_t> body);

}  // namespace rs4sim::rs4::protocol
