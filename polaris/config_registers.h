#pragma once
// EXTENSION: the barrier's configuration over Modbus. The manual says the barrier can be
// configured and auto-calibrated "by a Modbus command" [Polaris manual §7.2] [Polaris manual §7.4]
// but prints no register map; this block of holding registers is the project's own
// (docs/polaris.md "Configuration registers", [docs/decisions.md#polaris-config-registers]).
//
// The block starts at kConfigBase = 0x0100 (256), below the lowest start address of the
// data block (500 [Polaris manual §7.4.2]), so the two never overlap whatever start address
// is written. FC 3 and FC 4 read it, FC 6 and FC 16 write it
// [Modbus application protocol V1.1b3 §6.6] [Modbus application protocol V1.1b3 §6.12].
// Parsing the PDU is modbus/pdu.h's; this file gives the registers their meaning.

#include "codec/error_category.h"
#include "modbus/pdu.h"
#include "polaris/options.h"

#include <cstdint>
#include <span>
#include <string_view>
#include <system_error>
#include <vector>

namespace rs4sim::polaris {

inline constexpr std::uint16_t kConfigBase = 0x0100;

// The registers, by address; the value ranges are in kConfigRanges / docs/polaris.md.
enum class ConfigRegister : std::uint16_t {
  kDataMode = kConfigBase,  // 0 485MB, 1 FL1, 2 FL4, 3 FL10
  kStartAddress,            // 500..12287: the data block's first register (slave)
  kDirection,               // 0 direct, 1 reverse
  kDetection,               // 0 object, 1 hole
  kPn2Filter,               // 1..255 scans
  kScanTime,                // 5..5000 ms (the master's send period)
  kBitOrder,                // 0 LSB first, 1 MSB first (485MB)
  kNakMode,                 // 1 exception 07 on CRC error/bad function, 0 standard Modbus
  kCommand,                 // write 1: start auto-calibration; 2: manual adjustment; 0: nothing; reads 0
  kStatus,                  // read-only: 0 idle, 1 calibrating, 2 manual adjustment
  kCalibrations,            // read-only: auto-calibrations completed (wraps at 65535)
  kBeams,                   // read-only: N beams of the barrier
};
inline constexpr std::uint16_t kConfigRegisterCount = 12;
inline constexpr std::uint16_t kConfigEnd = kConfigBase + kConfigRegisterCount;  // exclusive
inline constexpr std::uint16_t kCommandStartCalibration = 1;
// "the manual adjustment can be activated by sending the ModBus command" [Polaris manual §7.2].
inline constexpr std::uint16_t kCommandManualAdjustment = 2;

[[nodiscard]] constexpr bool in_config_block(std::uint16_t address) noexcept {
  return address >= kConfigBase && address < kConfigEnd;
}

// Why a read or write of the block is refused; each maps to one Modbus exception code.
enum class ConfigError : std::uint8_t {
  kUnknownRegister = 1,  // an address outside the block           -> 02
  kReadOnly,             // a write to status, calibrations, beams  -> 02
  kBadQuantity,          // a register count outside 1..125 / 1..123, or a malformed PDU -> 03
  kOutOfRange,           // a value outside its register's range    -> 03
  kInvalidOptions,       // the options would fail Options::validate() -> 03
  kBusy,                 // start auto-calibration while one runs   -> 06
  kBeamsInterrupted,     // start auto-calibration with beams interrupted -> 04
};
[[nodiscard]] std::string_view to_string(ConfigError e) noexcept;
constexpr const char* error_category_name(ConfigError) noexcept { return "polaris.config"; }
inline std::error_code make_error_code(ConfigError e) noexcept {
  return codec::make_error_code_of(e);
}
// The exception code a refusal is answered with (02, 03, 04 or 06).
[[nodiscard]] modbus::ExceptionCode exception_for(ConfigError e) noexcept;

// What the status registers show.
struct CalibrationStatus {
  bool calibrating = false;
  std::uint16_t completed = 0;
  bool manual_adjustment = false;
};

// `quantity` registers from `start`; kUnknownRegister when any lies outside the block.
[[nodiscard]] std::error_code read_config(const Options& o, const CalibrationStatus& status,
                                          std::uint16_t start, std::uint16_t quantity,
                                          std::vector<std::uint16_t>& out);

// The result of a write: the options it leaves and whether it starts auto-calibration.
struct ConfigWrite {
  Options options;
  bool start_calibration = false;
  bool manual_adjustment = false;
};
// Writes `words` from `start` onto a copy of `current` (all or nothing): addresses first
// (kUnknownRegister, kReadOnly), then each value's range (kOutOfRange), then validate()
// (kInvalidOptions). `out` is set only on success; the caller decides about kBusy.
[[nodiscard]] std::error_code write_config(const Options& current, std::uint16_t start,
                                           std::span<const std::uint16_t> words, ConfigWrite& out);

}  // namespace rs4sim::polaris

template <>
struct std::is_error_code_enum<rs4sim::polaris::ConfigError> : std::true_type {};
