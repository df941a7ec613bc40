#pragma once
// Adapter commands written by a class 1 master ([RS4 manual §5.2.2],
// [RS4 manual §5.2.2], tables 5.2-3 … 5.2-8). The first payload byte of a reassembled WRITE
// decides: one of the codes below is an adapter command, checked for length and
// parameter range; any other byte is an RS4 command forwarded unchecked.
// Whether the writer may use adapter commands (class 1 only) is the adapter's call.

#include "rs4/protocol/errors.h"

#include <cstdint>
#include <span>
#include <variant>
#include <vector>

namespace rs4sim::rs4::protocol {

enum class AdapterCommandCode : std::uint8_t {
  kError = 0x84,            // PROFI_CMD_ERROR: last adapter error ([RS4 manual §5.2.2.4])
  kGetVersion = 0x90,       // PROFI_CMD_GET_VERSION ([RS4 manual §5.2.2.3])
  kGetError = 0x91,         // PROFI_CMD_GET_ERROR: error memory ([RS4 manual §5.2.2.5])
  kGetRs4Data = 0x92,       // PROFI_CMD_GET_RS4_DATA: forwarding of RS4 telegrams
                            // ([RS4 manual §5.2.2.2])
  kErrorInTelegram = 0x93,  // answer only: "error in telegram" (table 5.2-3)
  kReset = 0x94,            // PROFI_CMD_RESET ([RS4 manual §5.2.2.1])
  // EXTENSION ([docs/proxy-protocol.md]): the proxy's two adapter commands.
  kProxyBegin = 0x98,  // PROFI_CMD_PROXY_BEGIN: why a sync is requested, which direction
  kProxyEnd = 0x99,    // PROFI_CMD_PROXY_END: sync done (OSSD release) or failed
};

// PROFI_CMD_GET_RS4_DATA byte 6 (table 5.2-5); 0 stops all forwarding.
inline constexpr std::uint8_t kForwardMeasurement = 0x01;  // 0x23 COM_CMD_MESS_16_RT
inline constexpr std::uint8_t kForwardAlive = 0x02;        // 0x14 COM_CMD_ALIVE
inline constexpr std::uint8_t kForwardWarning = 0x04;      // 0x54 COM_CMD_WARNING_OCCURE
inline constexpr std::uint8_t kForwardError = 0x08;        // 0x53 COM_CMD_ERROR_OCCURE
inline constexpr std::uint8_t kForwardMaskDefined = 0x0F;

// The mask bit that selects an RS4 telegram code for forwarding (0x23 → bit 0,
// 0x14 → bit 1, 0x54 → bit 2, 0x53 → bit 3); 0 for any other code.
std::uint8_t forward_mask_bit(std::uint8_t telegram_code) noexcept;

// PROFI_CMD_GET_RS4_DATA byte 7: > 1 is invalid.
enum class ForwardMode : std::uint8_t { kOnce = 0, kPermanent = 1 };

struct ResetCommand {  // 94
  friend bool operator==(const ResetCommand&, const ResetCommand&) = default;
};
struct GetRs4DataCommand {  // 92 mask mode
  std::uint8_t mask = 0;
  ForwardMode mode = ForwardMode::kOnce;
  friend bool operator==(const GetRs4DataCommand&, const GetRs4DataCommand&) = default;
};
struct GetVersionCommand {  // 90
  friend bool operator==(const GetVersionCommand&, const GetVersionCommand&) = default;
};
struct GetLastErrorCommand {  // 84
  friend bool operator==(const GetLastErrorCommand&, const GetLastErrorCommand&) = default;
};
struct GetErrorMemoryCommand {  // 91
  friend bool operator==(const GetErrorMemoryCommand&, const GetErrorMemoryCommand&) = default;
};

// EXTENSION ([docs/proxy-protocol.md]). `98`: the proxy starts the sync the adapter asked for
// (Proxy-Request → 0); the answer says why and in which direction (adapter_answer.h).
struct ProxyBeginCommand {
  friend bool operator==(const ProxyBeginCommand&, const ProxyBeginCommand&) = default;
};
enum class ProxyOutcome : std::uint8_t { kSucceeded = 0, kFailed = 1 };
// `99 outcome error_hi error_lo`: kSucceeded (error 0) releases the OSSD bit; kFailed rolls
// the RS4 back to factory settings and enters `error` (0, or one of the proxy errors
// 0x2B01..0x2B2F of [RS4 manual §5.3] table 5.3-3) in the error memory with a diagnosis alarm.
struct ProxyEndCommand {
  ProxyOutcome outcome = ProxyOutcome::kSucceeded;
  std::uint16_t error = 0;
  friend bool operator==(const ProxyEndCommand&, const ProxyEndCommand&) = default;
};
// The adapter error numbers a kFailed PROFI_CMD_PROXY_END may carry (0 = none).
[[nodiscard]] bool is_proxy_end_error(std::uint16_t error) noexcept;

// Table 5.2-3 byte 6.
enum class CommandErrorKind : std::uint8_t { kWrongLength = 0, kWrongParameter = 1 };

// A faulty adapter command; the following READ answers `93 kind command`.
struct RejectedCommand {
  CommandErrorKind kind = CommandErrorKind::kWrongLength;
  std::uint8_t command = 0;
  friend bool operator==(const RejectedCommand&, const RejectedCommand&) = default;
};

// Not an adapter command: the bytes go to the RS4 unchanged (views the input).
struct Rs4Command {
  std::span<const std::uint8_t> bytes;
};

using WriteCommand = std::variant<Rs4Command, ResetCommand, GetRs4DataCommand, GetVersionCommand,
                                  GetLastErrorCommand, GetErrorMemoryCommand, ProxyBeginCommand,
                                  ProxyEndCommand, RejectedCommand>;

// Classifies a reassembled WRITE payload. The only error is kEmptyCommand; a bad
// adapter command is a RejectedCommand value (it has a prescribed answer).
Result<WriteCommand> parse_write_command(std::span<const std::uint8_t> payload);

// Master side: the WRITE payload of each adapter command.
std::vector<std::uint8_t> encode_command(const ResetCommand&);
std::vector<std::uint8_t> encode_command(const GetRs4DataCommand& command);
std::vector<std::uint8_t> encode_command(const GetVersionCommand&);
std::vector<std::uint8_t> encode_command(const GetLastErrorCommand&);
std::vector<std::uint8_t> encode_command(const GetErrorMemoryCommand&);
std::vector<std::uint8_t> encode_command(const ProxyBeginCommand&);
std::vector<std::uint8_t> encode_command(const ProxyEndCommand& command);

// The 0x93 answer (table 5.2-3): 93 kind command.
std::vector<std::uint8_t> encode_rejection(const RejectedCommand& rejected);
Result<RejectedCommand> decode_rejection(std::span<const std::uint8_t> answer);

}  // namespace rs4sim::rs4::protocol
