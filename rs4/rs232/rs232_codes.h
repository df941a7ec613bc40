#pragma once
// The command set of the RS4's own RS232 interface behind the optical PC adapter, as rs4sim
// answers it (docs/rs232.md). The framing and the codes 0x14, 0x16, 0x17, 0x19, 0x23, 0x24 are
// those of the public RS4/ROD4 drivers ([roboticslibrary/rl LeuzeRs4.cpp]); the telegrams
// 0x14/0x23/0x53/0x54 are the manual's ([RS4 manual §5.2.3]). Everything else is EXTENSION:
// the password check 0x10, the measurement window 0x20, the stream switch 0x22, and the
// parameter-set commands 0x60..0x65 that share their payloads with the PROFIBUS-side proxy
// commands ([docs/proxy-protocol.md], rs4/protocol/parameter_transfer.h).

#include "rs4/adapter/rs4_commands.h"
#include "stream/line_settings.h"

#include <array>
#include <cstdint>
#include <optional>

namespace rs4sim::rs4::rs232 {

enum class Rs232Code : std::uint8_t {
  kCheckPassword = 0x10,      // EXTENSION: a protected no-op (password frame of docs/rs232.md)
  kAlive = 0x14,              // COM_CMD_ALIVE ([RS4 manual §5.2.3.1])
  kAck = 0x16,                // positive acknowledge ([roboticslibrary/rl LeuzeRs4.cpp])
  kNak = 0x17,                // negative acknowledge ([roboticslibrary/rl LeuzeRs4.cpp])
  kSetBaud = 0x19,            // baud change ([roboticslibrary/rl LeuzeRs4.cpp])
  kMeasurementWindow = 0x20,  // EXTENSION: resolution, start, stop into the parameter set
  kStreamControl = 0x22,      // EXTENSION: continuous 0x23 on (1) / off (0)
  kMeasurement = 0x23,        // COM_CMD_MESS_16_RT ([RS4 manual §5.2.3.4])
  kRequestScan = 0x24,        // one 0x23 on request ([roboticslibrary/rl LeuzeRs4.cpp])
  kErrorOccure = 0x53,        // COM_CMD_ERROR_OCCURE ([RS4 manual §5.2.3.2])
  kWarningOccure = 0x54,      // COM_CMD_WARNING_OCCURE ([RS4 manual §5.2.3.3])
};
[[nodiscard]] constexpr std::uint8_t byte(Rs232Code c) noexcept {
  return static_cast<std::uint8_t>(c);
}

// Error numbers, rates and the factory password: the RS4 command set's, one for both paths
// (rs4/adapter/rs4_commands.h). Carried by 0x53 (command without acknowledge) or 0x17
// (command with OPT1 bit 6).
inline constexpr std::uint16_t kErrorWrongPassword = adapter::kRs4ErrorWrongPassword;
inline constexpr std::uint16_t kErrorBadData = adapter::kRs4ErrorBadData;
inline constexpr std::uint16_t kErrorNotOperational = adapter::kRs4ErrorNotOperational;
using adapter::baud_code;
using adapter::baud_of_code;
using adapter::kBaudRates;
using adapter::kFactoryPassword;
inline constexpr std::uint32_t kDefaultBaud = 57600;
// 8N1 at `baud`: the RS4's character format ([roboticslibrary/rl LeuzeRs4.cpp]).
[[nodiscard]] stream::LineSettings line_8n1(std::uint32_t baud) noexcept;

}  // namespace rs4sim::rs4::rs232
