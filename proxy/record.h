#pragma once
// What ProxySync asks of the bus and what comes back, free of dp/master: a driver turns a
// RecordRequest into a DPV1 MSAC_C1 WRITE or READ of slot 0, index 2 ([RS4 manual §5.2]) and
// feeds the outcome back as a RecordResult (docs/proxy.md "Driver").

#include <cstdint>
#include <variant>
#include <vector>

namespace rs4sim::proxy {

inline constexpr std::uint8_t kRecordSlot = 0;    // [RS4 manual §5.2]: slot 0 only
inline constexpr std::uint8_t kRecordIndex = 2;   // index 2 (3 is treated identically)
inline constexpr std::uint8_t kReadLength = 240;  // the longest record ([RS4 manual §5.2])

// DPV1 WRITE of these bytes (one block: header + payload).
struct RecordWrite {
  std::vector<std::uint8_t> data;
  friend bool operator==(const RecordWrite&, const RecordWrite&) = default;
};
// DPV1 READ of up to `length` bytes.
struct RecordRead {
  std::uint8_t length = kReadLength;
  friend bool operator==(const RecordRead&, const RecordRead&) = default;
};
using RecordRequest = std::variant<RecordWrite, RecordRead>;

// The outcome of one WRITE or READ. `sfc` is ERROR_CODE_SFC ([RS4 manual §6.4]) for a failed
// one: Error_Code_1 << 8 | Error_Code_2 of the DPV1 negative response ([IEC 61158-6-3 MSAC_C1]),
// 0x0000 when no negative response arrived (timeout, slave not in data exchange).
struct RecordResult {
  bool ok = false;
  std::vector<std::uint8_t> data;  // READ: the record's bytes
  std::uint16_t sfc = 0;

  static RecordResult success(std::vector<std::uint8_t> bytes = {}) {
    return RecordResult{true, std::move(bytes), 0};
  }
  static RecordResult negative(std::uint8_t error_code_1, std::uint8_t error_code_2) {
    return RecordResult{false, {}, static_cast<std::uint16_t>((error_code_1 << 8) | error_code_2)};
  }
  static RecordResult no_response() { return RecordResult{false, {}, 0}; }
};

}  // namespace rs4sim::proxy
