#pragma once
// The Proxy-FB's retentive state ([RS4 manual §6.4]: "34 retentive bytes" behind
// START_ADDRESS_REM_MARKER), rs4sim's version: a fixed 24-byte record the owner persists
// (a file, the archive, …) whenever it changes, so that a restart mid-sync fails safely
// (docs/proxy.md "Retentive record"). All values high byte first:
//   0       format version (kRetentiveVersion)
//   1       state: 0 idle, 1 a device sync is open (98 written, 99 not confirmed),
//           2 background verify after the release
//   2       Step (positions.h) the machine was in
//   3       flags: bit 0 CONFIG_SET_TO_DEFAULT, bit 1 FB_BUSY, bit 2 a download is open
//   4..5    ERROR_NUMBER_FB
//   6..7    ERROR_CODE_SFC
//   8..9    ERROR_NUMBER_RS4
//   10      direction the device asked for (SyncDirection of the 98 answer)
//   11      reason (SyncReason of the 98 answer)
//   12..15  serial number the device reported (IDENTIFY)
//   16..19  CRC-32 of the set being synchronised
//   20..23  CRC-32/ISO-HDLC of bytes 0..19

#include <array>
#include <cstdint>
#include <optional>
#include <span>

namespace rs4sim::proxy {

inline constexpr std::size_t kRetentiveSize = 24;
inline constexpr std::uint8_t kRetentiveVersion = 1;

enum class RetentiveState : std::uint8_t { kIdle = 0, kSyncOpen = 1, kBackgroundVerify = 2 };

struct RetentiveRecord {
  RetentiveState state = RetentiveState::kIdle;
  std::uint8_t step = 0;
  bool config_set_to_default = false;
  bool fb_busy = false;
  bool download_open = false;
  std::uint16_t error_number_fb = 0;
  std::uint16_t error_code_sfc = 0;
  std::uint16_t error_number_rs4 = 0;
  std::uint8_t direction = 0;
  std::uint8_t reason = 0;
  std::uint32_t serial_number = 0;
  std::uint32_t set_crc32 = 0;
  friend bool operator==(const RetentiveRecord&, const RetentiveRecord&) = default;
};

std::array<std::uint8_t, kRetentiveSize> encode_retentive(const RetentiveRecord& record);
// nullopt for a wrong size, version, state, flags or checksum.
std::optional<RetentiveRecord> decode_retentive(std::span<const std::uint8_t> bytes);

}  // namespace rs4sim::proxy
