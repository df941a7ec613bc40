#pragma once
// Error numbers of the PROFIsafe adapter ([RS4 manual §5.3.2, table 5.3-3]).
// They appear in the diagnosis alarm ([RS4 manual §5.3.2]), in the answers to
// PROFI_CMD_ERROR / PROFI_CMD_GET_ERROR ([RS4 manual §5.2.2]) and as std::error_code inside the
// project (category adapter_category(), message = the manual's cause and remedy).

#include "codec/error_category.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>

namespace rs4sim::rs4::protocol {

enum class AdapterError : std::uint16_t {
  kSafetyDriverCannotCheckOutputs = 0x2418,  // PROFIsafe driver cannot check cyclic outputs
  kOutputsInconsistent = 0x2419,             // processing outputs gives no consistent result
  kWrongFieldPair = 0x2600,                  // wrong field pair number
  kTelegramNotProcessed = 0x2A04,            // PROFIBUS telegram could not be processed
  kReadBuffersFull = 0x2A05,                 // all read buffers occupied
  kTelegramTooLong = 0x2A06,                 // PROFIBUS telegram too long (>= 1100 bytes)
  kUnexpectedBlockNumber = 0x2A0B,           // unexpected block number
  kProxyStateUnknown = 0x2B01,               // unknown state of the Proxy-FB
  kCrcComparison = 0x2B09,                   // error in CRC comparison
  kEchoCrcWrong = 0x2B10,                    // 0x2B1x: echo data CRC no. x wrong (x = 0..F)
  kCrcDiffersOnReread = 0x2B20,              // 0x2B2x: CRC no. x differs on read repetition
};

// 0x2B1x / 0x2B2x with the CRC number x (0..15) in the low nibble.
AdapterError echo_crc_wrong(std::uint8_t crc_number) noexcept;
AdapterError crc_differs_on_reread(std::uint8_t crc_number) noexcept;
// x of a 0x2B1x / 0x2B2x code; nullopt for every other code.
std::optional<std::uint8_t> crc_number(AdapterError e) noexcept;

// The wire value as a table 5.3-3 code, or nullopt when it is none of them.
std::optional<AdapterError> adapter_error_from_wire(std::uint16_t value) noexcept;
constexpr std::uint16_t to_wire(AdapterError e) noexcept { return static_cast<std::uint16_t>(e); }

// Table 5.3-3 columns "Ursache / Bedeutung" and "Maßnahme zur Fehlerbehebung".
std::string_view adapter_error_cause(AdapterError e) noexcept;
std::string_view adapter_error_remedy(AdapterError e) noexcept;

// The cause; the category's message is "0x2A0B: <cause> (remedy: <remedy>)".
[[nodiscard]] std::string_view to_string(AdapterError e) noexcept;
[[nodiscard]] std::string error_message(AdapterError e);
constexpr const char* error_category_name(AdapterError) noexcept { return "rs4.adapter"; }
inline std::error_code make_error_code(AdapterError e) noexcept {
  return codec::make_error_code_of(e);
}
inline const std::error_category& adapter_category() noexcept {
  return codec::category_of<AdapterError>();
}

}  // namespace rs4sim::rs4::protocol
