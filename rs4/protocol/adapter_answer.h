#pragma once
// READ answers of the adapter commands ([RS4 manual §5.2.2]; manual tables
// 5.2-6, 5.2-7, 5.2-8) and the error memory they report. Payload only: the block
// header is added by BlockSplitter.

#include "rs4/protocol/errors.h"

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace rs4sim::rs4::protocol {

// PROFI_CMD_GET_VERSION answer, table 5.2-6 (10 bytes, code 0x90 first). The defaults
// are the values the manual lists; the three DPV1 slave firmware bytes are the
// emulated device's own.
struct VersionAnswer {
  std::uint8_t profisafe_version_hi = 1;  // PROFIsafe version 1.0
  std::uint8_t profisafe_version_lo = 0;
  std::uint8_t dp_version_hi = 1;  // PROFIBUS DP version 1.0
  std::uint8_t dp_version_lo = 0;
  std::uint8_t dpv1sl_components_hi = 0x11;  // VISL_COMP_INSTALLED_C2 | _DPC31
  std::uint8_t dpv1sl_components_lo = 0x0D;  // _C2 | _SUB_AL | _SUB_CH1
  std::uint8_t main_interface = 0;           // DPV1SL main interface
  std::uint8_t function = 0;                 // DPV1SL function
  std::uint8_t bugfix = 0;                   // DPV1SL bugfix
  friend bool operator==(const VersionAnswer&, const VersionAnswer&) = default;
};
inline constexpr std::size_t kVersionAnswerSize = 10;
std::vector<std::uint8_t> encode_version_answer(const VersionAnswer& answer);
Result<VersionAnswer> decode_version_answer(std::span<const std::uint8_t> answer);

// PROFI_CMD_ERROR answer, table 5.2-7 (9 bytes, code 0x84 first). DECISION
// ([docs/decisions.md#rs4-uc1-count-byte-order]): every 2-byte value high byte first, also the μC1
// count the manual lists lo, hi.
struct LastErrorAnswer {
  std::uint16_t uc2_error = 0;
  std::uint16_t uc2_count = 0;  // occurrences since power-on
  std::uint16_t uc1_error = 0;
  std::uint16_t uc1_count = 0;
  friend bool operator==(const LastErrorAnswer&, const LastErrorAnswer&) = default;
};
inline constexpr std::size_t kLastErrorAnswerSize = 9;
std::vector<std::uint8_t> encode_last_error_answer(const LastErrorAnswer& answer);
Result<LastErrorAnswer> decode_last_error_answer(std::span<const std::uint8_t> answer);

// One processor's error memory (table 5.2-8): a ring of 20 error numbers, the index of
// the newest entry and an age flag (0 = an error occurred in the last cycle, 1 = older).
// The project's choice where the manual is silent: an empty memory holds zeros, write
// index 19 (so the first push lands in slot 0) and age flag 1.
struct ErrorRingBuffer {
  static constexpr std::size_t kEntries = 20;
  std::array<std::uint16_t, kEntries> entries{};
  std::uint8_t write_index = kEntries - 1;
  std::uint8_t age_flag = 1;

  // Enters an error: the write index moves on (wrapping after 19), the number is
  // stored there and the age flag becomes 0.
  void push(std::uint16_t error) noexcept;
  // The adapter's cycle passed without a new error: age flag 1.
  void mark_aged() noexcept { age_flag = 1; }
  std::uint16_t newest() const noexcept { return entries[write_index % kEntries]; }
  friend bool operator==(const ErrorRingBuffer&, const ErrorRingBuffer&) = default;
};

// PROFI_CMD_GET_ERROR answer, table 5.2-8: 85 bytes = 91, μC2 index, μC2 age,
// 20 × (hi, lo), μC1 index, μC1 age, 20 × (hi, lo).
struct ErrorMemoryAnswer {
  ErrorRingBuffer uc2;
  ErrorRingBuffer uc1;
  friend bool operator==(const ErrorMemoryAnswer&, const ErrorMemoryAnswer&) = default;
};
inline constexpr std::size_t kErrorMemoryAnswerSize = 85;
std::vector<std::uint8_t> encode_error_memory_answer(const ErrorMemoryAnswer& answer);
Result<ErrorMemoryAnswer> decode_error_memory_answer(std::span<const std::uint8_t> answer);

// ---- EXTENSION: the proxy's adapter commands ([docs/proxy-protocol.md]) --------------------
// Why the adapter set Proxy-Request ([RS4 manual §7.1, §7.2]).
enum class SyncReason : std::uint8_t {
  kNone = 0,                 // no sync requested: nothing was started
  kPowerUp = 1,              // the RS4 became operational after power-on / adapter start
  kPcAdapterRemoved = 2,     // the PC adapter was removed: the set may have changed
  kRetry = 3,                // Proxy-Request again after a failed sync
  kUserParametrisation = 4,  // a user changed the set over PROFIBUS (password): upload it
};
// The direction the device wants (it decides, as an IO-Link Data Storage device does).
enum class SyncDirection : std::uint8_t {
  kNone = 0,
  kVerify = 1,    // the device has a set: the proxy compares identity and checksum, then
                  // releases at once or downloads its stored set (device exchange)
  kUpload = 2,    // the device's set is new (parametrised through the PC adapter): store it
  kDownload = 3,  // the device holds factory settings: download the stored set, if any
};
// "none", "verify", "upload", "download" (the API's word).
[[nodiscard]] std::string_view to_token(SyncDirection d) noexcept;
// PROFI_CMD_PROXY_BEGIN answer: 98 reason direction flags (4 bytes).
struct ProxyBeginAnswer {
  SyncReason reason = SyncReason::kNone;
  SyncDirection direction = SyncDirection::kNone;
  bool factory_default = false;  // flags bit 0: the RS4 holds its factory setting
  friend bool operator==(const ProxyBeginAnswer&, const ProxyBeginAnswer&) = default;
};
inline constexpr std::size_t kProxyBeginAnswerSize = 4;
std::vector<std::uint8_t> encode_proxy_begin_answer(const ProxyBeginAnswer& answer);
Result<ProxyBeginAnswer> decode_proxy_begin_answer(std::span<const std::uint8_t> answer);

// PROFI_CMD_PROXY_END answer: 99 accepted flags (3 bytes). accepted = 0 when no sync was
// running (nothing changed); flags bit 0 = the RS4 now holds its factory setting.
struct ProxyEndAnswer {
  bool accepted = false;
  bool factory_default = false;
  friend bool operator==(const ProxyEndAnswer&, const ProxyEndAnswer&) = default;
};
inline constexpr std::size_t kProxyEndAnswerSize = 3;
std::vector<std::uint8_t> encode_proxy_end_answer(const ProxyEndAnswer& answer);
Result<ProxyEndAnswer> decode_proxy_end_answer(std::span<const std::uint8_t> answer);

}  // namespace rs4sim::rs4::protocol
