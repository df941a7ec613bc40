#pragma once
// An RTU frame [Modbus serial line V1.02 §2.5.1]: address, function, data, CRC-16 (low
// byte first). 4..256 bytes on the wire; the framer cuts frames by t3.5 of silence.

#include "modbus/error.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <system_error>
#include <vector>

namespace rs4sim::modbus {

inline constexpr std::size_t kMinFrameSize = 4;
inline constexpr std::size_t kMaxFrameSize = 256;
inline constexpr std::uint8_t kBroadcastAddress = 0;
// The individual (slave) addresses; 248..255 are reserved [Modbus serial line V1.02 §2.2].
inline constexpr std::uint8_t kMinSlaveAddress = 1;
inline constexpr std::uint8_t kMaxSlaveAddress = 247;
[[nodiscard]] constexpr bool is_slave_address(long long address) noexcept {
  return address >= kMinSlaveAddress && address <= kMaxSlaveAddress;
}
inline constexpr std::uint8_t kExceptionFlag = 0x80;

struct RtuFrame {
  std::uint8_t address = 0;
  std::uint8_t function = 0;
  std::vector<std::uint8_t> data;  // between the function byte and the CRC

  friend bool operator==(const RtuFrame&, const RtuFrame&) = default;
};

// The wire bytes of `frame`, CRC appended (data longer than 252 bytes is the caller's bug:
// the result is then longer than kMaxFrameSize).
[[nodiscard]] std::vector<std::uint8_t> encode(const RtuFrame& frame);

// Checks the size and the CRC and splits `wire` into `out`. `out` is untouched on error.
[[nodiscard]] std::error_code decode(std::span<const std::uint8_t> wire, RtuFrame& out);

}  // namespace rs4sim::modbus
