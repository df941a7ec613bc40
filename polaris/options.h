#pragma once
// The Polaris barrier's configuration, as the PC tool "Polaris Read & Config" sets it
// [Polaris manual §7.4.2], plus the emulator's own switches (marked DECISION/EXTENSION in
// docs/polaris.md). The app parses flags into it; validate() says what is wrong.

#include "polaris/model.h"
#include "stream/clock.h"
#include "stream/line_settings.h"

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rs4sim::polaris {

// What the barrier transmits [Polaris manual §7.4.3, §8.2]: one bit per beam (485MB) or
// (first, last) pairs of 1, 4 or 10 objects plus the overall pair (FL1/FL4/FL10).
enum class DataMode : std::uint8_t { k485Mb, kFl1, kFl4, kFl10 };
enum class Role : std::uint8_t { kSlave, kMaster };
// Direct: beam 1 next to the connector cap; reverse: beam 1 at the far cap.
enum class ScanDirection : std::uint8_t { kDirect, kReverse };
// What PN2 reports: two objects at once, or a hole confirmed for pn2_filter scans.
enum class Detection : std::uint8_t { kObject, kHole };
// 485MB: which bit of a word is the lowest beam (the manual does not say; DECISION LSB).
enum class BitOrder : std::uint8_t { kLsbFirst, kMsbFirst };

// The PC tool's "Data storage" and "Storage mode" [Polaris manual §7.4.2] (polaris/storage.h).
enum class DataStorage : std::uint8_t { kNone, kObject, kHole };
enum class StorageMode : std::uint8_t { kTemporary, kPermanent };
// Which maximum response time column of the model tables is one scan
// [Polaris manual §2.1, §2.2] ([docs/decisions.md#polaris-response-time]).
enum class ResponseColumn : std::uint8_t { kFirst = 1, kSecond = 2 };

[[nodiscard]] std::string_view to_string(DataMode m) noexcept;
// "slave", "master" (the API's and the CLI's word).
[[nodiscard]] constexpr std::string_view to_token(Role r) noexcept {
  return r == Role::kSlave ? "slave" : "master";
}
[[nodiscard]] std::optional<DataMode> parse_data_mode(std::string_view text) noexcept;
// The CLI's --mode words and the API's strings: "direct"/"reverse", "object"/"hole",
// "lsb"/"msb".
[[nodiscard]] constexpr std::string_view to_token(ScanDirection d) noexcept {
  return d == ScanDirection::kDirect ? "direct" : "reverse";
}
[[nodiscard]] constexpr std::string_view to_token(Detection d) noexcept {
  return d == Detection::kObject ? "object" : "hole";
}
[[nodiscard]] constexpr std::string_view to_token(BitOrder b) noexcept {
  return b == BitOrder::kLsbFirst ? "lsb" : "msb";
}
// "storage=none|object|hole", "temporary"/"permanent".
[[nodiscard]] std::string_view to_token(DataStorage s) noexcept;
[[nodiscard]] std::optional<DataStorage> parse_data_storage(std::string_view text) noexcept;
[[nodiscard]] constexpr std::string_view to_token(StorageMode m) noexcept {
  return m == StorageMode::kTemporary ? "temporary" : "permanent";
}

struct Options {
  Family family = Family::kPl10;
  std::uint16_t beams = 16;  // a count the family makes (PL10-160: 16 beams)
  std::uint8_t address = 1;  // own address (slave) or the target slave's (master), 1..247
  std::uint32_t baud = 19200;
  DataMode mode = DataMode::k485Mb;
  Role role = Role::kSlave;
  std::optional<std::uint16_t> start_address;  // default 0x2000 (slave), 0 (master)
  ScanDirection direction = ScanDirection::kDirect;
  Detection detection = Detection::kObject;
  std::uint16_t pn2_filter = 1;              // scans that confirm a hole, 1..255
  std::chrono::milliseconds scan_time{100};  // master send period, 5..5000 ms
  // One scan of the barrier; a slave answers when the scan in progress ends. Zero: the
  // model's first maximum response time [Polaris manual §2.1, §2.2]
  // ([docs/decisions.md#polaris-response-time]).
  stream::Duration response_time{};
  // The model table's column response_time = 0 takes; the second: the slower one.
  ResponseColumn response_column = ResponseColumn::kFirst;
  bool nak_on_error = true;  // exception 0x07 on CRC error/bad function; false: standard
  BitOrder bit_order = BitOrder::kLsbFirst;
  DataStorage storage = DataStorage::kNone;
  StorageMode storage_mode = StorageMode::kTemporary;
  // The initial scene: physical beams interrupted from the start (1..beams), as
  // gridscan::Options and metron::Options hold theirs.
  std::vector<std::uint16_t> blocked;

  // Empty when usable; otherwise one sentence naming the field, the value and the rule.
  [[nodiscard]] std::string validate() const;
};

inline constexpr std::uint16_t kDefaultSlaveStart = 0x2000;
inline constexpr std::uint16_t kMinSlaveStart = 500;
inline constexpr std::uint16_t kMaxSlaveStart = 12287;
// The longest scan response_time may set (the slowest model's second column is 34,7 ms).
inline constexpr std::chrono::milliseconds kMaxResponseTime{1000};

// The first register of the data block.
[[nodiscard]] std::uint16_t start_address(const Options& o) noexcept;
// The scan duration: response_time, or the model's maximum response time of
// response_column (a beam count no model has, which validate() refuses: the next larger
// model's).
[[nodiscard]] stream::Duration scan_duration(const Options& o) noexcept;
[[nodiscard]] stream::LineSettings line_settings(const Options& o) noexcept;

}  // namespace rs4sim::polaris
